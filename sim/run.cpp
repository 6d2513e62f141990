#include "sim/run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <optional>
#include <sstream>

#include <GeographicLib/Constants.hpp>
#include <nlohmann/json.hpp>

#include "common/atomic_file.hpp"
#include "common/constants.hpp"
#include "common/error.hpp"
#include "common/limits.hpp"
#include "common/number_text.hpp"
#include "common/progress.hpp"
#include "nav/attitude.hpp"
#include "nav/strapdown.hpp"
#include "sim/aided/aided_output.hpp"
#include "sim/imu_source.hpp"
#include "sim/nav_loop.hpp"
#include "sim/output.hpp"
#include "sim/filter_summary.hpp"
#include "sim/run_report.hpp"
#include "sim/scenario_aiding.hpp"
#include "sim/trajectory.hpp"
#include "common/json_text.hpp"

namespace sinsim::sim {
namespace {

/// An error beyond the Earth's radius is no navigation error any more (a model in the wrong unit,
/// a noise no strapdown can integrate): said, with where it peaked; the run is written as computed.
std::string beyondEarthWarning(const RunSummary& s) {
  const double radius = GeographicLib::Constants::WGS84_a();
  if (!(s.maxHorizontal > radius || s.maxVertical > radius)) return {};
  const bool h = s.maxHorizontal >= s.maxVertical;
  return std::string("the ") + (h ? "horizontal" : "vertical") + " error reached " +
         limits::fmt((h ? s.maxHorizontal : s.maxVertical) / 1e3, 3) + " km (at t = " +
         limits::fmt(h ? s.maxHorizontalTime : s.maxVerticalTime, 6) + " s), beyond the Earth's radius (" +
         limits::fmt(radius / 1e3, 5) + " km): the navigation solution means nothing there. Sensor errors this "
         "large (model " + s.model + ") are beyond what strapdown navigation integrates: check the model's units";
}

const char* kStateHeader = "t_s,lat_deg,lon_deg,h_m,vn_mps,ve_mps,vd_mps,roll_deg,pitch_deg,yaw_deg\n";
const char* kErrorHeader = "t_s,north_m,east_m,down_m,vn_mps,ve_mps,vd_mps,roll_rad,pitch_rad,yaw_rad\n";

// NaN never reaches an output file: a non-finite row stops the run (the OutputFiles guard then
// removes the temporaries), with the time it happened.
void requireFiniteRow(std::initializer_list<double> row, double t, const char* what,
                      double bound = std::numeric_limits<double>::infinity()) {
  for (double v : row)
    if (!(std::fabs(v) <= bound) || !std::isfinite(v))
      throw NumericalError(std::string("the ") + what + " became non-finite at t = " +
                           limits::fmt(t, 9) +
                           " s: the motion or the IMU errors are beyond what the simulation "
                           "holds (docs/limits.md); nothing was written");
}

// 12 decimals of a degree are 0.1 µm on the ground: the CSV does not hide sub-millimetre drifts.
// Longitudes in (−180°, 180°], the truth's as the navigated one's (the motion's own is unwrapped).
void writeState(std::FILE* f, const nav::NavState& s) {
  const nav::Vec3 e = nav::eulerFromQuat(s.q_nb) * kDegPerRad;
  requireFiniteRow({s.lat, s.lon, s.h, s.v_n.x(), s.v_n.y(), s.v_n.z(), e.x(), e.y(), e.z()}, s.t,
                   "navigation state");
  std::fprintf(f, "%.6f,%.12f,%.12f,%.6f,%.9f,%.9f,%.9f,%.9f,%.9f,%.9f\n", s.t, s.lat * kDegPerRad,
               nav::wrapAngle(s.lon) * kDegPerRad, s.h, s.v_n.x(), s.v_n.y(), s.v_n.z(), e.x(), e.y(), e.z());
}

}  // namespace

void requireFiniteError(const NavError& e, double bound) {
  requireFiniteRow({e.pos_n.x(), e.pos_n.y(), e.pos_n.z(), e.vel_n.x(), e.vel_n.y(), e.vel_n.z(),
                    e.euler.x(), e.euler.y(), e.euler.z()},
                   e.t, "navigation error", bound);
}

namespace {

void writeError(std::FILE* f, const NavError& e) {
  std::fprintf(f, "%.6f,%.6e,%.6e,%.6e,%.6e,%.6e,%.6e,%.6e,%.6e,%.6e\n", e.t, e.pos_n.x(),
               e.pos_n.y(), e.pos_n.z(), e.vel_n.x(), e.vel_n.y(), e.vel_n.z(), e.euler.x(),
               e.euler.y(), e.euler.z());
}

nlohmann::json errorJson(const NavError& e) {
  return {{"t_s", e.t},
          {"north_m", e.pos_n.x()},
          {"east_m", e.pos_n.y()},
          {"down_m", e.pos_n.z()},
          {"horizontal_m", e.horizontal()},
          {"vertical_m", e.vertical()},
          {"velocity_mps", e.vel_n.norm()},
          {"roll_rad", e.euler.x()},
          {"pitch_rad", e.euler.y()},
          {"yaw_rad", e.euler.z()}};
}

// The scenario's aided navigation, or nullptr for a free-inertial run from the true start (which
// then runs exactly as without aiding keys).
std::unique_ptr<ScenarioAiding> makeAiding(const Scenario& sc, const RunOptions& opt,
                                           const nav::Earth& earth,
                                           const errormodels::StreamKey& key) {
  if (sc.aiding.inert()) return nullptr;
  if (opt.aiding)
    throw InputError("scenario " + sc.name + " has its own aiding (initial_errors, alignment, "
                     "gnss, filter) and the caller passed another aiding hook");
  return std::make_unique<ScenarioAiding>(earth, sc, key);
}

/// Every file a run may write into its folder.
constexpr const char* kRunFiles[] = {"truth.csv", "nav.csv", "errors.csv", "filter.csv", "imu.csv",
                                     "summary.json"};

/// Refuses a report written over one of the run's own files (`-o out --html out/truth.csv` wrote
/// the page over the truth, exit 0).
void refuseReportOverRunFile(const std::string& html, const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path page = fs::weakly_canonical(html, ec);
  if (ec) return;  // the report's own checks (AtomicFile) say what is wrong with it
  for (const char* name : kRunFiles)
    if (page == fs::weakly_canonical(fs::path(dir) / name, ec) && !ec)
      throw InputError("--html " + html + " is the run's own " + name + " in " + dir +
                       ": give the report another name");
}

/// The run's file names in dir that this run does not write (imu.csv without --imu, filter.csv
/// of a free-inertial run): an earlier run's, which summary.json would not list.
std::vector<std::string> staleRunFiles(const std::string& dir, const std::vector<std::string>& written) {
  std::vector<std::string> stale;
  std::error_code ec;
  for (const char* name : kRunFiles)
    if (std::find(written.begin(), written.end(), name) == written.end() &&
        std::filesystem::is_regular_file(std::filesystem::path(dir) / name, ec))
      stale.push_back(name);
  return stale;
}

}  // namespace

NavError navError(const nav::Earth& earth, const nav::NavState& nav, const nav::NavState& truth) {
  NavError e;
  e.t = truth.t;
  double M = 0.0, N = 0.0;
  earth.radii(truth.lat, M, N);
  e.pos_n = nav::Vec3((nav.lat - truth.lat) * (M + truth.h),
                      nav::wrapAngle(nav.lon - truth.lon) * (N + truth.h) * std::cos(truth.lat),
                      -(nav.h - truth.h));
  e.vel_n = nav.v_n - truth.v_n;
  const nav::Vec3 en = nav::eulerFromQuat(nav.q_nb), et = nav::eulerFromQuat(truth.q_nb);
  for (int i = 0; i < 3; ++i) e.euler[i] = nav::wrapAngle(en[i] - et[i]);
  return e;
}

RunSummary run(const Scenario& sc, const RunOptions& opt) {
  const auto wallStart = std::chrono::steady_clock::now();

  // --- validate everything before any file exists -------------------------------------------
  errormodels::ImuErrorModel model = sc.errors;
  if (opt.model) {
    model = *opt.model == "none" ? errormodels::ImuErrorModel::none()
                                 : errormodels::ImuErrorModel::load(*opt.model);
    requireTemperatureFor(sc, model, model.source());
  }
  const std::uint64_t seed = opt.seed ? *opt.seed : sc.seed.value_or(0);
  std::unique_ptr<errormodels::ImuCorruptor> corruptor;
  if (!model.empty()) corruptor = model.instantiate(sc.imuRate, {seed, opt.runIndex});

  const nav::Earth& earth = sharedEarth();
  const Trajectory trajectory(earth, sc.motion());
  TrajectorySource source(trajectory, sc.imuRate, corruptor.get(), sc.temperature);
  std::unique_ptr<ScenarioAiding> aiding = makeAiding(sc, opt, earth, {seed, opt.runIndex});
  const long long decimation = sc.decimation();

  // --- outputs --------------------------------------------------------------------------------
  std::unique_ptr<OutputFiles> out;
  std::unique_ptr<FolderLock> lock;
  std::FILE *fTruth = nullptr, *fNav = nullptr, *fErr = nullptr, *fFilter = nullptr, *fImu = nullptr;
  if (!opt.outDir.empty()) {
    out = std::make_unique<OutputFiles>(opt.outDir);
    lock = std::make_unique<FolderLock>(opt.outDir);  // a second writer is refused
    removeStaleTemporaries(opt.outDir, false);            // of a run killed while writing
    fTruth = out->open("truth.csv");
    fNav = out->open("nav.csv");
    fErr = out->open("errors.csv");
    std::fputs(kStateHeader, fTruth);
    std::fputs(kStateHeader, fNav);
    std::fputs(kErrorHeader, fErr);
    if (aiding && sc.aiding.filter.enabled) {  // initial errors or an alignment alone: no filter rows
      aided::writeFilterHeader(fFilter = out->open("filter.csv"));
      aiding->writeFilterRows(fFilter);
    }
    if (opt.writeImu) aided::writeImuHeader(fImu = out->open("imu.csv"));
  }

  std::unique_ptr<RunTrack> track;
  std::optional<AtomicFile> html;  // after `out`: destroyed first, its temporary before the folder
  if (!opt.htmlPath.empty()) {
    if (out) refuseReportOverRunFile(opt.htmlPath, out->dir());
    // Opened now: a missing folder, a folder, a device or an input is refused before the run
    // (it was after the outputs had been committed, which stayed behind).
    html.emplace(opt.htmlPath);
    track = std::make_unique<RunTrack>(source.initial(),
                                       source.sampleCount() / decimation + 1);
  }

  RunSummary s;
  if (fTruth) {
    s.files = {"truth.csv", "nav.csv", "errors.csv"};
    if (fFilter) s.files.push_back("filter.csv");
    if (fImu) s.files.push_back("imu.csv");
    s.files.push_back("summary.json");
  }
  s.scenario = sc.name;
  s.model = model.source();
  s.seed = seed;
  s.duration = static_cast<double>(source.sampleCount()) * (1.0 / sc.imuRate);  // as IdealImu::dt()
  s.imuSamples = source.sampleCount();
  if (aiding) s.warnings = aided::startWarnings(earth, sc.aiding, sc.strapdown, source.initial());
  if (std::string w = sc.durationWarning(); !w.empty()) s.warnings.insert(s.warnings.begin(), std::move(w));
  if (sc.aiding.filter.enabled) s.filter = filterSummaryLine(sc.aiding.filter);
  double sumH2 = 0.0, sumV2 = 0.0;
  long long rows = 0;
  double prevSpeed = source.initial().v_n.norm();
  NavError err;
  auto onEpoch = [&](const ImuEpoch& e, const nav::NavState& navState) {
    if ((e.index & 0xffff) == 0)
      progress::update("navigating", std::uint64_t(e.index), std::uint64_t(source.sampleCount()));
    if (fImu && e.index > 0) aided::writeImuRow(fImu, e.ideal, e.measured);
    err = navError(earth, navState, e.truth);
    if (e.index > 0) {
      const double speed = e.truth.v_n.norm();
      s.distance += 0.5 * (prevSpeed + speed) * e.ideal.dt;  // trapezoid
      prevSpeed = speed;
      if (err.horizontal() > s.maxHorizontal || !std::isfinite(err.horizontal())) {
        s.maxHorizontal = err.horizontal();
        s.maxHorizontalTime = err.t;
      }
      if (err.vertical() > s.maxVertical || !std::isfinite(err.vertical())) {
        s.maxVertical = err.vertical();
        s.maxVerticalTime = err.t;
      }
    }
    if (e.index % decimation != 0) return;
    sumH2 += err.horizontal() * err.horizontal();
    sumV2 += err.vertical() * err.vertical();
    ++rows;
    requireFiniteError(err);  // with or without files: the Python module returned NaN arrays
    if (opt.onRow) opt.onRow(err);
    if (track) track->add(e.truth, navState, err);
    if (out) {
      writeState(fTruth, e.truth);
      writeState(fNav, navState);
      writeError(fErr, err);
    }
  };
  NavLoopOptions loop;
  loop.strapdown = sc.strapdown;
  loop.biasWindow = opt.biasWindow;
  loop.aiding = aiding ? aiding.get() : opt.aiding;
  loop.cancel = &progress::interruptFlag();
  // An interruption unwinds through `out`, which removes the unfinished files.
  if (!navigate(source, loop, onEpoch)) throw Interrupted();
  s.final = err;
  if (aiding) s.outages = aiding->aided().outages();
  if (aiding)
    if (std::string w = aiding->innovationWarning(); !w.empty()) s.warnings.push_back(std::move(w));
  if (std::string w = beyondEarthWarning(s); !w.empty()) s.warnings.push_back(std::move(w));
  s.rmsHorizontal = std::sqrt(sumH2 / static_cast<double>(rows));
  s.rmsVertical = std::sqrt(sumV2 / static_cast<double>(rows));

  if (out) {
    nlohmann::json j;
    j["scenario"] = {{"name", sc.name}, {"file", sc.file}, {"description", sc.description}};
    j["model"] = {{"source", model.source()}, {"effects", model.empty() ? std::vector<std::string>{}
                                                                        : model.effectNames()}};
    j["seed"] = seed;
    j["run_index"] = opt.runIndex;
    j["duration_s"] = s.duration;
    j["imu_rate_hz"] = sc.imuRate;
    j["output_rate_hz"] = sc.outputRate;
    j["imu_samples"] = s.imuSamples;
    j["output_rows"] = rows;
    j["vertical_channel"] = verticalName(sc.strapdown.vertical);
    if (sc.strapdown.vertical == nav::VerticalChannel::Damped)
      j["vertical_time_constant_s"] = sc.strapdown.dampingTimeConstant;
    if (sc.temperature.present)
      j["temperature"] = {{"start_K", sc.temperature.start}, {"rate_K_per_s", sc.temperature.rate}};
    j["distance_m"] = s.distance;
    j["final_error"] = errorJson(s.final);
    j["max_error"] = {{"horizontal_m", s.maxHorizontal},
                      {"horizontal_t_s", s.maxHorizontalTime},
                      {"vertical_m", s.maxVertical},
                      {"vertical_t_s", s.maxVerticalTime},
                      {"over", "every IMU epoch"}};
    j["rms_error"] = {{"horizontal_m", s.rmsHorizontal},
                      {"vertical_m", s.rmsVertical},
                      {"over", "the rows of errors.csv"}};
    if (s.distance > 0.0)
      j["final_horizontal_error_percent_of_distance"] = 100.0 * s.final.horizontal() / s.distance;
    j["files"] = {{"truth", "truth.csv"}, {"nav", "nav.csv"}, {"errors", "errors.csv"}};
    if (fFilter) j["files"]["filter"] = "filter.csv";
    if (fImu) j["files"]["imu"] = "imu.csv";
    for (const aided::OutageResult& o : s.outages)
      j["outages"].push_back({{"start_s", o.window.start}, {"end_s", o.window.end},
                              {"max_horizontal_m", o.maxHorizontal}, {"at_s", o.t},
                              {"filter_sigma_horizontal_m", o.sigmaHorizontal}});
    if (sc.aiding.filter.enabled) j["filter"] = filterSummaryJson(sc.aiding.filter);
    const std::vector<std::string> stale = staleRunFiles(out->dir(), s.files);
    for (const std::string& name : stale)
      s.warnings.push_back(name + " in " + out->dir() + " was an earlier run's (this run writes none): removed");
    if (!s.warnings.empty()) j["warnings"] = s.warnings;
    std::FILE* fSum = out->open("summary.json");
    const std::string text = jsonText(j, 2);
    std::fputs(text.c_str(), fSum);
    out->commit();
    s.outDir = out->dir();
    std::error_code ec;  // after the commit: a failed run removes nothing
    for (const std::string& name : stale) std::filesystem::remove(std::filesystem::path(out->dir()) / name, ec);
  }
  if (track) {
    std::fputs(runReportHtml(s, *track).c_str(), html->file());
    html->commit();
    s.report = opt.htmlPath;
  }
  s.wallTime =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  return s;
}

std::string summaryLine(const RunSummary& s) {
  std::ostringstream os;
  os << s.scenario << ": " << s.duration << " s, " << lengthText(s.distance, 3) << " travelled, "
     << "model " << s.model << "; final horizontal error " << lengthText(s.final.horizontal(), 3)
     << " (max " << lengthText(s.maxHorizontal, 3) << "), vertical " << lengthText(s.final.vertical(), 3);
  return os.str();
}

}  // namespace sinsim::sim
