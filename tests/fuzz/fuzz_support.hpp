// What a fuzz target may do with an input: succeed, or throw sinsim's own input error. Anything
// else — another exception, a crash, a sanitizer report, a leak, more than -rss_limit_mb or
// -timeout — is a finding (libFuzzer reports an escaping exception as a crash via abort()).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "common/error.hpp"

namespace sinsim::fuzz {

/// Runs f(text); returns normally when f succeeds or throws sinsim::InputError.
template <class F>
void expectInputErrorOnly(const std::uint8_t* data, std::size_t size, F&& f) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    f(text);
  } catch (const sinsim::InputError&) {
  }
}

}  // namespace sinsim::fuzz
