// The YAML reader must locate every problem by file, line (1-based, as an editor shows it) and
// key path, and report all problems of a file at once.
#include <catch2/catch.hpp>

#include "common/config.hpp"

using namespace sinsim;
using Catch::Matchers::Contains;

TEST_CASE("values are read with units and problems are collected with line and key path") {
  ConfigFile f = ConfigFile::fromString(
      "start:\n"            // line 1
      "  latitude: 45 deg\n"  // line 2
      "  height: 10 s\n"      // line 3: wrong dimension
      "  speeed: 3 m/s\n"     // line 4: unknown key, close to "speed"
      "segments:\n"           // line 5
      "  - type: static\n"    // line 6
      "    duration: -3 s\n",  // line 7
      "scenario.yaml");
  ConfigNode root = f.root();
  root.allowKeys({"start", "segments"});
  ConfigNode start = root["start"];
  start.allowKeys({"latitude", "height", "speed"});
  CHECK(start.quantity("latitude", Dimension::angle()) == Approx(0.7853981633974483));
  start.quantity("height", Dimension::length());
  start.quantity("longitude", Dimension::angle());  // missing
  auto segs = root["segments"].items();
  REQUIRE(segs.size() == 1);
  double d = segs[0].quantity("duration", Dimension::time());
  segs[0]["duration"].check(d > 0, "expected a positive time");

  REQUIRE(f.hasErrors());
  const auto& ds = f.diagnostics();
  REQUIRE(ds.size() == 4);
  CHECK(ds[0].line == 4);
  CHECK(ds[0].key == "start.speeed");
  CHECK_THAT(ds[0].message, Contains("did you mean \"speed\""));
  CHECK(ds[1].line == 3);
  CHECK(ds[1].key == "start.height");
  CHECK(ds[2].key == "start.longitude");
  CHECK_THAT(ds[2].message, Contains("missing key"));
  CHECK(ds[3].line == 7);
  CHECK(ds[3].key == "segments[0].duration");
  CHECK_THAT(ds[3].str(), Contains("scenario.yaml:7: segments[0].duration: expected a positive"));
  REQUIRE_THROWS_AS(f.throwIfErrors(), ConfigError);
}

TEST_CASE("YAML syntax errors and missing files throw at once with a location") {
  REQUIRE_THROWS_WITH(ConfigFile::fromString("a: [1, 2\nb: 3\n", "bad.yaml"),
                      Contains("bad.yaml:"));
  REQUIRE_THROWS_WITH(ConfigFile::load("/nonexistent/x.yaml"), Contains("cannot open file"));
}

TEST_CASE("choices list the allowed values") {
  ConfigFile f = ConfigFile::fromString("vertical: floating\n", "s.yaml");
  f.root().choice("vertical", {"free", "held", "damped"}, "free");
  REQUIRE(f.diagnostics().size() == 1);
  CHECK_THAT(f.diagnostics()[0].message, Contains("free, held, damped"));
  CHECK(f.diagnostics()[0].line == 1);
}

TEST_CASE("a tree built in code (fromNode) is read like a file, problems by key path, no line") {
  YAML::Node root(YAML::NodeType::Map);
  root["start"]["latitude"] = "45 deg";
  root["start"]["hieght"] = "10 m";
  root["segments"].push_back(YAML::Node(YAML::NodeType::Map));
  root["segments"][0]["duration"] = "3 kg";
  ConfigFile f = ConfigFile::fromNode(root, "<scenario dict>");
  ConfigNode start = f.root()["start"];
  start.allowKeys({"latitude", "height"});
  CHECK(start.quantity("latitude", Dimension::angle()) == Approx(0.7853981633974483));
  f.root()["segments"].items()[0].quantity("duration", Dimension::time());
  REQUIRE(f.diagnostics().size() == 2);
  for (const Diagnostic& d : f.diagnostics()) CHECK(d.line == 0);  // a dict has no lines
  CHECK(f.diagnostics()[0].key == "start.hieght");
  CHECK(f.diagnostics()[1].key == "segments[0].duration");
  CHECK_THROWS_WITH(f.throwIfErrors(), Contains("<scenario dict>: segments[0].duration: "));
}
