// The parts of the module, one file each, registered by module.cpp.
#pragma once

#include <pybind11/pybind11.h>

#include "errormodels/imu_model.hpp"
#include "python/convert.hpp"

namespace sinsim::python {

void bindExceptions(py::module_& m);  // module.cpp: sinsim.Error, InputError, ConfigError, ...
void bindModel(py::module_& m);       // bind_model.cpp: Model, load_model
void bindSimulate(py::module_& m);    // bind_simulate.cpp: Scenario, run, mc, synth
void bindIdentify(py::module_& m);    // bind_identify.cpp: load_record, analyze, fit, diagnose

/// The simulator's model of a Model (ImuErrorModel::fromSpec), named by its source or label.
errormodels::ImuErrorModel imuModel(const Model& m);

}  // namespace sinsim::python
