// Helpers shared by several test suites.
#pragma once

#include <string>
#include <vector>

#include "common/error.hpp"

namespace sinsim::test {

/// Is there a diagnostic of `file` at `line` for key path `key` whose message contains `fragment`?
inline bool hasDiagnostic(const std::vector<Diagnostic>& ds, const std::string& file, int line,
                          const std::string& key, const std::string& fragment) {
  for (const auto& d : ds)
    if (d.file == file && d.line == line && d.key == key &&
        d.message.find(fragment) != std::string::npos)
      return true;
  return false;
}

}  // namespace sinsim::test
