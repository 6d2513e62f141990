#include "common/error.hpp"

#include <algorithm>

#include "common/limits.hpp"

namespace sinsim {

std::string Diagnostic::str() const {
  std::string s = file;
  if (line > 0) s += ":" + std::to_string(line);
  s += ": ";
  if (!key.empty()) s += key + ": ";
  s += message;
  return s;
}

namespace {
// At most kMaxReportedErrors problems are spelled out; 100,000 bad coefficients give 21 lines.
std::string joinDiagnostics(const std::vector<Diagnostic>& ds) {
  std::string s;
  const std::size_t shown = std::min(ds.size(), limits::kMaxReportedErrors);
  for (std::size_t i = 0; i < shown; ++i) {
    if (!s.empty()) s += "\n";
    s += ds[i].str();
  }
  if (ds.size() > shown)
    s += "\n... and " + std::to_string(ds.size() - shown) + " more problem(s) in " + ds[shown].file;
  return s;
}
}  // namespace

ConfigError::ConfigError(std::vector<Diagnostic> diagnostics)
    : InputError(joinDiagnostics(diagnostics)), diagnostics_(std::move(diagnostics)) {}

void rethrowWithContext(const std::string& where, const Error& e) {
  const std::string& what = e.text();
  // A bad option's value is the command line's, not the file's: kept as it is (exit 2).
  if (dynamic_cast<const OptionError*>(&e)) throw OptionError(what);
  if (what.rfind(where, 0) == 0) throw InputError(what);
  // "FILE: channel gx is constant" already names the file: add only the missing part.
  const std::size_t colon = where.find(": ");
  if (colon != std::string::npos && what.rfind(where.substr(0, colon + 2), 0) == 0)
    throw InputError(what);
  throw InputError(where + ": " + what);
}

}  // namespace sinsim
