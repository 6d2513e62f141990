// The Python module `sinsim` (docs/python.md). Library exceptions become Python exceptions with
// the same messages (file, line, key path):
//   sinsim.Error (RuntimeError)  <- sinsim::Error
//   sinsim.InputError (Error, ValueError)  <- sinsim::InputError (bad input of any kind)
//   sinsim.ConfigError (InputError)  <- sinsim::ConfigError; .diagnostics: [(file, line, key, message)]
//   sinsim.NumericalError (Error)  <- sinsim::NumericalError
#include <pybind11/pybind11.h>

#include "common/error.hpp"
#include "common/limits.hpp"
#include "common/progress.hpp"
#include "python/bindings.hpp"

namespace sinsim::python {

void bindExceptions(py::module_& m) {
  const py::module_ builtins = py::module_::import("builtins");
  const py::object type = builtins.attr("type");
  auto make = [&](const char* name, py::tuple bases, const char* doc) {
    py::dict ns;
    ns["__module__"] = "sinsim";
    ns["__doc__"] = doc;
    py::object cls = type(name, bases, ns);
    m.attr(name) = cls;
    return cls.release();  // kept for the translator for the life of the process
  };
  static const py::handle error = make("Error", py::make_tuple(builtins.attr("RuntimeError")),
                                       "Any error sinsim raises on purpose.");
  static const py::handle input =
      make("InputError", py::make_tuple(error, builtins.attr("ValueError")),
           "Bad input: a scenario, model, record or argument that cannot be used as given.");
  static const py::handle config =
      make("ConfigError", py::make_tuple(input),
           "Every problem of one input (file or dict), each with file, line and key path; "
           ".diagnostics lists them as (file, line, key, message).");
  static const py::handle numerical = make("NumericalError", py::make_tuple(error),
                                           "A numerical condition that valid input should not reach.");
  // Messages reach Python as str: bytes that are not UTF-8 (a Latin-1 key or file name) are shown
  // as \xNN, or the str could not be made and a UnicodeDecodeError would replace the error.
  py::register_exception_translator([](std::exception_ptr p) {
    auto text = [](const std::string& s) { return limits::messageText(s); };
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ConfigError& e) {
      py::list diags;
      for (const Diagnostic& d : e.diagnostics())
        diags.append(py::make_tuple(text(d.file), d.line, text(d.key), text(d.message)));
      py::object ex = py::reinterpret_borrow<py::object>(config)(text(e.text()));
      ex.attr("diagnostics") = diags;
      PyErr_SetObject(config.ptr(), ex.ptr());
    } catch (const InputError& e) {
      PyErr_SetString(input.ptr(), text(e.text()).c_str());
    } catch (const NumericalError& e) {
      PyErr_SetString(numerical.ptr(), text(e.text()).c_str());
    } catch (const Error& e) {
      PyErr_SetString(error.ptr(), text(e.text()).c_str());
    } catch (const Interrupted&) {  // Ctrl-C in a call (python/interrupt.hpp)
      PyErr_SetNone(PyExc_KeyboardInterrupt);
    }
  });
}

}  // namespace sinsim::python

PYBIND11_MODULE(sinsim, m) {
  m.doc() = "sinsim: strapdown INS simulator and inertial error-model lab (docs/python.md)";
  sinsim::python::bindExceptions(m);
  sinsim::python::bindModel(m);
  sinsim::python::bindSimulate(m);
  sinsim::python::bindIdentify(m);
}
