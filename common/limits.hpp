// Every size and range limit of sinsim's input, in one place (documented in docs/limits.md).
//
// They bound the work and memory any input file can ask for, so that a small hostile or mistyped
// file fails at once with a clear message instead of running until killed: each limit is far
// beyond what a real scenario, model or record needs and well inside what 2 cores and a few GB
// finish in minutes. Checks happen where a file is read, before anything is expanded or allocated.
#pragma once

#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>

#include "common/constants.hpp"

namespace sinsim::limits {

// ---- YAML files (scenarios, models) ---------------------------------------------------------
/// [bytes] Largest YAML file read (the biggest shipped file is ~5 KB).
constexpr std::size_t kMaxYamlBytes = 4u << 20;
/// Nodes of one YAML file, counting every alias expansion as read: a 1 KB file of nested aliases
/// (a "billion laughs") stops here instead of expanding to GBs. Also bounds a model's size (its
/// effects and coefficients; an AR effect has its own order limit).
constexpr std::size_t kMaxYamlNodeVisits = 500000;
/// Problems listed in one error message; the rest are counted ("and N more").
constexpr std::size_t kMaxReportedErrors = 20;
/// [characters] Longest piece of an offending value echoed in a message.
constexpr std::size_t kMaxEchoChars = 80;
/// Largest magnitude of any quantity in SI units read from a file or record (1e12 m is 7 AU,
/// 1e12 s is 30,000 years): beyond it products such as density² · rate overflow towards inf.
constexpr double kMaxQuantity = 1e12;

// ---- Rates and time -------------------------------------------------------------------------
/// [Hz] Range of an IMU or stochastic-process sample rate, and of a record's sample rate.
/// Real IMUs sample at 1 Hz to a few kHz; 1 mHz admits slow logs (temperature, clocks).
constexpr double kMinRate = 1e-3;
constexpr double kMaxRate = 1e5;
/// Most worker threads a command starts (--threads): beyond, thread creation fails
/// (100,000 asked for 100,000 runs) long before it could help on any machine.
constexpr unsigned kMaxThreads = 1024;
/// [s] Longest scenario (10 days) and shortest segment (one sample of the fastest IMU rate).
constexpr double kMaxDuration = 864000.0;
constexpr double kMinSegmentDuration = 1e-5;
/// Largest sample count of a simulated signal (duration × rate): ~4 min of a 2-core machine
/// per 1e8 strapdown steps; 10 days at 100 Hz is 8.64e7.
constexpr double kMaxSamples = 1e8;
/// [rad] Largest |latitude| of a start or of the motion: the NED frame (lon' = vE / ((N + h)
/// cos lat)) is singular at the poles.
constexpr double kMaxLatitude = 89.0 * kRadPerDeg;
/// Largest number of segments after expanding every `repeat`: laying out and integrating a
/// segment costs ~2 µs, and 1,000,000 segments from two nested repeats of a 100-byte file took
/// 2.3 s of CPU before the first IMU sample (10 s under the sanitizers).
constexpr std::size_t kMaxSegments = 100000;

// ---- Error models ---------------------------------------------------------------------------
/// Largest order of an AR effect, and of an AR fit (`sinsim fit --order/--max-order`): a fitted
/// model must load back. 64 lags at 1 kHz reach 64 ms, beyond what an AR of raw IMU data resolves.
constexpr int kMaxArOrder = 64;

/// Largest number of effects in one error model (all sensors, axes and lists): a real model has
/// a few per axis; 20,000 white-noise effects made `diagnose` run for minutes.
constexpr std::size_t kMaxModelEffects = 1000;

// ---- Motion ---------------------------------------------------------------------------------
/// [m] Height range of a trajectory (below the Dead Sea floor to the edge of space).
constexpr double kMinHeight = -1.2e4;
constexpr double kMaxHeight = 1.0e5;
/// [m/s] Highest speed of a trajectory (above orbital speed).
constexpr double kMaxSpeed = 1.2e4;

/// [rad/s] Highest angular rate a trajectory segment may reach (10,000 deg/s): 2.5 times the
/// widest MEMS gyro range (±4000 deg/s); a 1e6 deg turn in 1 s ran at 3.5e6 deg/s with exit 0.
constexpr double kMaxAngularRate = 1e4 * kRadPerDeg;
/// [m/s^2] Highest acceleration of a trajectory (about 1000 g): 5 times the widest MEMS
/// accelerometer range (±200 g); reaching 11 km/s in 1 s asked for 2200 g.
constexpr double kMaxAcceleration = 1e4;

/// [K] Highest sensor temperature of a scenario's profile (1000 degC; sensors are specified to
/// ~125 degC): `rate: 1e10 degC/s` reached 2e11 degC and ran.
constexpr double kMaxTemperature = 1273.15;
/// [bytes] Largest temperature CSV (`synth --temperature FILE`): 1 Hz for 10 days is ~15 MB.
constexpr std::size_t kMaxTemperatureCsvBytes = std::size_t{64} << 20;

// ---- Records (CSV) --------------------------------------------------------------------------
/// [characters] Longest line of a record (a comment line before the header included). The text is
/// read in chunks and parsed as it comes, so only a line is ever held: a 1 MB gzip of one 600 MB
/// line used to be read whole (std::bad_alloc at 1 GiB of text).
constexpr std::size_t kMaxRecordLineChars = std::size_t{1} << 20;
/// Largest number of columns of a record.
constexpr std::size_t kMaxRecordColumns = 64;
/// Largest number of cells (rows × columns): 8 bytes each in memory (2.4 GB at the limit); a
/// 4-h record at 2 kHz with 10 columns (2.9e8) -- the longest and fastest static records the
/// diagnosis is asked to take.
constexpr std::size_t kMaxRecordCells = 300000000;
/// [characters] Longest field of a record (a double needs at most ~25).
constexpr std::size_t kMaxFieldChars = 64;

/// `text` for a message: at most kMaxEchoChars characters, longer ones cut with a note of the
/// full length; control characters (NUL, escapes) and bytes that are not UTF-8 (Latin-1) shown
/// as \xNN.
std::string echo(std::string_view text);

/// A whole message for the terminal: bytes that are not UTF-8 (a Latin-1 file name or key) shown
/// as \xNN, control characters too except line ends and tabs.
std::string messageText(std::string_view text);

/// Does duration × rate exceed kMaxSamples (or is either not finite)? The product is formed in
/// floating point before any integer conversion.
inline bool tooManySamples(double duration, double rate) {
  const double n = duration * rate;
  return !(std::isfinite(n) && n <= kMaxSamples);
}

// ---- Monte Carlo -----------------------------------------------------------------------------
/// Largest number of runs per model of `sinsim mc` (4e9 used to end in std::bad_alloc).
constexpr double kMaxMcRuns = 1e7;
/// [bytes] Largest size of a Monte Carlo batch's errors held for the statistics: models (with
/// budget variants) × runs × output epochs × error fields × 4 bytes.
constexpr double kMaxMcResultBytes = 4.0 * (1u << 30);

/// "1e+05" style number with enough digits to tell it from its neighbours (up to 12).
std::string fmt(double x, int digits = 6);

/// Throws InputError "`what`: expected 0 (every core) to kMaxThreads worker threads" beyond.
void requireThreads(unsigned threads, const std::string& what);

}  // namespace sinsim::limits
