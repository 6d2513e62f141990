// The error models of a Monte Carlo batch as the command line names them: model files (or
// "none"), each labelled by its file stem (made unique), identified by its content for resume.
#pragma once

#include <string>
#include <vector>

#include "sim/montecarlo.hpp"
#include "sim/scenario.hpp"

namespace sinsim::sim {

/// Loads `files` ("none": the perfect IMU); no files: the scenario's own errors, identified by
/// scenarioIdentity. Throws InputError (ConfigError for a bad file) for a model that needs a
/// temperature the scenario lacks or that cannot run at the scenario's IMU rate — before any file
/// of the batch is written.
std::vector<McModel> loadMcModels(const std::vector<std::string>& files, const Scenario& scenario,
                                  const std::string& scenarioIdentity);

}  // namespace sinsim::sim
