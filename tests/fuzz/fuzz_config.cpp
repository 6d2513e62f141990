// libFuzzer target: the YAML config reader (common/config) walked through every accessor a
// scenario or model reader uses: keys, items, quantities of several dimensions, integers, bools.
#include "common/config.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace {

void walk(const sinsim::ConfigNode& n, int depth) {
  using sinsim::Dimension;
  if (depth > 64) return;
  if (n.isMap()) {
    n.allowKeys({"type", "duration", "rate", "a", "sigma", "gyro", "accel"});
    for (const std::string& k : n.keys()) walk(n[k], depth + 1);
    n.quantity("duration", Dimension::time(), 0.0);
    n.integer("count", 1);
    n.boolean("enabled", true);
    n.choice("mode", {"free", "held"}, "free");
  } else if (n.isSequence()) {
    for (const auto& item : n.items()) walk(item, depth + 1);
  } else if (n.isScalar()) {
    n.asQuantity(Dimension::frequency());
    n.asQuantity(Dimension::angularRate() * Dimension::time().sqrt());
    n.asNumber();
    n.asInteger();
    n.asBool();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  sinsim::fuzz::expectInputErrorOnly(data, size, [](const std::string& text) {
    sinsim::ConfigFile file = sinsim::ConfigFile::fromString(text, "fuzz.yaml");
    walk(file.root(), 0);
    file.throwIfErrors();
  });
  return 0;
}
