// libFuzzer target: the scenario parser (segments, repeats, aliases, inline and external error
// models). The file system is sandboxed: every input file must lie inside an empty temporary
// folder, so `errors: /etc/...` or `errors: /dev/zero` are refused like missing files.
#include <cstdlib>
#include <filesystem>
#include <string>

#include "common/read_file.hpp"
#include "sim/scenario.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace {
const std::string& sandbox() {
  static const std::string dir = [] {
    std::string tmpl = (std::filesystem::temp_directory_path() / "sinsim-fuzz-XXXXXX").string();
    const char* made = ::mkdtemp(tmpl.data());
    if (made == nullptr) std::abort();
    sinsim::restrictInputFilesTo(made);
    return std::string(made);
  }();
  return dir;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& dir = sandbox();
  sinsim::fuzz::expectInputErrorOnly(data, size, [&](const std::string& text) {
    sinsim::sim::parseScenario(text, dir + "/fuzz.yaml", dir);
  });
  return 0;
}
