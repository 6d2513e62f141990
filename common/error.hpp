// The one exception family of sinsim. Library code throws; only main() catches, prints and
// returns non-zero (the GeographicLib GeographicErr / tools pattern).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace sinsim {

/// Base of every error sinsim throws on purpose.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message), text_(message) {}
  explicit Error(const char* message) : std::runtime_error(message), text_(message) {}
  /// The whole message. what() is a C string that ends at a NUL byte a message may hold (a Python
  /// str's file name 'a\x00b.csv' reached Python as 'a'); text() does not.
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

/// Bad user input: a scenario, model file or data record that cannot be used as given.
class InputError : public Error {
 public:
  using Error::Error;
};

/// A command-line option's value that cannot be read ("--bias-window 5 m"): a bad command line,
/// which the CLI answers with exit code 2 as CLI11's own refusals (an InputError elsewhere).
class OptionError : public InputError {
 public:
  using InputError::InputError;
};

/// One problem found in an input file, located by file, line and key path.
struct Diagnostic {
  std::string file;     ///< path as the user gave it
  int line = 0;         ///< 1-based; 0 when unknown
  std::string key;      ///< YAML key path, e.g. "segments[2].duration"; empty for the whole file
  std::string message;  ///< what is wrong and what was expected

  /// "scenario.yaml:14: segments[2].duration: expected a positive time, got \"-3 s\""
  std::string str() const;
};

/// Every problem found in one input file, reported at once (OpenVINS-style: parse all, fail once).
class ConfigError : public InputError {
 public:
  explicit ConfigError(std::vector<Diagnostic> diagnostics);
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

 private:
  std::vector<Diagnostic> diagnostics_;
};

/// A scenario's motion that leaves what the simulation holds, found while simulating it (the
/// trajectory reaching a pole); the command that named the scenario adds its file.
class MotionError : public InputError {
 public:
  using InputError::InputError;
};

/// A numerical or internal condition that should not happen with valid input.
class NumericalError : public Error {
 public:
  using Error::Error;
};

/// An Error raised deep inside a computation (statistics, fitting: "burg: the series is
/// constant") rethrown as an InputError that says where: "`where`: message", e.g.
/// "run1.csv: channel gx: burg: ...". A message that already starts with `where` is kept as is; an
/// OptionError (a bad command-line value) is rethrown unchanged.
[[noreturn]] void rethrowWithContext(const std::string& where, const Error& e);

/// Runs f(); any sinsim::Error escaping it is rethrown by rethrowWithContext(where, ...).
template <class F>
decltype(auto) withContext(const std::string& where, F&& f) {
  try {
    return f();
  } catch (const Error& e) {
    rethrowWithContext(where, e);
  }
}

}  // namespace sinsim
