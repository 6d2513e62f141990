// A scenario: where the vehicle starts, how it moves (segments), how its IMU is sampled and
// corrupted, and how the navigation runs. Read from YAML once, at the edge; everything inside
// is SI. The file format is documented in docs/simulate.md ("Scenario files") and in
// scenarios/*.yaml.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/config.hpp"
#include "errormodels/imu_model.hpp"
#include "nav/strapdown.hpp"
#include "sim/aided/aiding_config.hpp"
#include "sim/motion.hpp"
#include "sim/temperature.hpp"

namespace sinsim::sim {

struct Scenario {
  std::string name;         // `name:` or the file stem
  std::string description;  // `description:` (free text)
  std::string file;         // path as given ("" for a scenario parsed from text)

  MotionStart start;
  std::vector<Segment> segments;  // planned, repeats expanded, back to back from t = 0

  double imuRate = 100.0;    // [Hz]
  double outputRate = 1.0;   // [Hz], divides imuRate
  nav::StrapdownOptions strapdown;

  errormodels::ImuErrorModel errors = errormodels::ImuErrorModel::none();
  TemperatureProfile temperature;
  std::optional<std::uint64_t> seed;  // `seed:`; the run's --seed overrides it
  /// initial_errors, alignment, gnss, filter (docs/aided.md); inert() for a free-inertial run.
  aided::AidingConfig aiding;

  double duration() const;  // [s], sum of the segment durations
  /// The default output folder's name: `prefix` + the name with every character but letters,
  /// digits, '.', '-' and '_' as '_' ("scenario" for an empty name, "." or ".."), so that a name
  /// never leads out of `out/` (a `name: ../x` or `/tmp/x` wrote there, `..` into the current
  /// folder).
  std::string folderName(const std::string& prefix = "") const;
  MotionProfile motion() const { return MotionProfile(start, segments); }
  /// IMU samples per output row: imuRate / outputRate (an integer by validation).
  long long decimation() const;
  /// A warning when the segments add up to no whole number of IMU intervals (the run ends at the
  /// nearest sample, before or after the last segment's end), else empty.
  std::string durationWarning() const;
};

/// Refuses a model with temperature-dependent effects for a scenario without `temperature:`
/// (`run --model`, `mc --model`, Python's models): InputError naming the scenario file, the model
/// (`label`) and the key to add.
void requireTemperatureFor(const Scenario& sc, const errormodels::ImuErrorModel& model,
                           const std::string& label);

/// Reads a scenario file. Every problem of the file (and of an error-model file it names) is
/// collected and thrown at once as a ConfigError whose diagnostics carry file, line and key path.
Scenario loadScenario(const std::string& path);

/// Parses scenario text as if read from the file `name`; relative model paths resolve against
/// baseDir. Same error behaviour as loadScenario.
Scenario parseScenario(const std::string& text, const std::string& name,
                       const std::string& baseDir = ".");

/// Reads a scenario from an already parsed file or tree (ConfigFile::fromNode: the Python
/// module's dicts); relative model paths resolve against baseDir. Same error behaviour.
Scenario parseScenario(ConfigFile& file, const std::string& baseDir = ".");

/// The segment type names a scenario may use, for help texts and messages.
std::vector<std::string> segmentTypes();

}  // namespace sinsim::sim
