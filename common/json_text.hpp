// JSON as text for a file: the one place every writer dumps a document. Strings that are not
// UTF-8 (a Latin-1 scenario name, a file name's raw bytes) are written with U+FFFD in place of
// the bad bytes instead of throwing nlohmann's type_error 316 at the end of a finished run.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace sinsim {

/// `j` indented by `indent` spaces per level, and a final newline.
inline std::string jsonText(const nlohmann::json& j, int indent) {
  return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace sinsim
