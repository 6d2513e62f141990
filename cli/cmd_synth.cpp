// `sinsim synth MODEL --rate HZ --duration S -o FILE.csv`: a static IMU record with a known error
// model, as a real IMU at rest would give it — test data with known truth for the identification
// path (including effects the fitted model does not know about).
//
// Output CSV, header `t,gx,gy,gz,ax,ay,az,temp`: t [s] (end of each interval), gx..gz [rad/s] and
// ax..az [m/s^2] = measured increments / dt in body axes (x fwd, y right, z down), temp [degC].
#include <cmath>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

#include "cli/commands.hpp"
#include "common/error.hpp"
#include "common/limits.hpp"
#include "common/read_file.hpp"
#include "common/units.hpp"
#include "errormodels/imu_model.hpp"
#include "nav/attitude.hpp"
#include "nav/earth.hpp"

namespace sinsim::cli {
namespace {

constexpr double kZeroCelsius = 273.15;  // [K]

/// Sensor temperature over the record [K]: a constant ("25 degC"), a linear ramp over the whole
/// record ("20 degC..45 degC"), or a CSV file with header t,temp (s, degC) interpolated linearly
/// and held constant outside its time span.
class TemperatureProfile {
 public:
  TemperatureProfile(const std::string& spec, double duration) : duration_(duration) {
    auto dots = spec.find("..");
    if (dots != std::string::npos) {
      try {
        t0_ = parseQuantityAs(spec.substr(0, dots), Dimension::temperature());
        t1_ = parseQuantityAs(spec.substr(dots + 2), Dimension::temperature());
      } catch (const InputError& e) {
        throw InputError("--temperature \"" + spec + "\": a ramp is \"20 degC..45 degC\": " +
                         e.what());
      }
      kind_ = Kind::ramp;
      return;
    }
    try {
      t0_ = parseQuantityAs(spec, Dimension::temperature());
      kind_ = Kind::constant;
      return;
    } catch (const InputError& e) {
      std::ifstream probe(spec);
      if (!probe) {
        throw InputError("--temperature \"" + spec + "\": neither a temperature (" + e.what() +
                         "), nor a ramp \"20 degC..45 degC\", nor a readable CSV file");
      }
    }
    readCsv(spec);
    kind_ = Kind::table;
  }

  double at(double t) const {
    switch (kind_) {
      case Kind::constant: return t0_;
      case Kind::ramp: return t0_ + (t1_ - t0_) * (duration_ > 0 ? t / duration_ : 0.0);
      case Kind::table: break;
    }
    if (t <= ts_.front()) return temps_.front();
    if (t >= ts_.back()) return temps_.back();
    while (t > ts_[i_ + 1]) ++i_;  // t only grows
    const double w = (t - ts_[i_]) / (ts_[i_ + 1] - ts_[i_]);
    return temps_[i_] + w * (temps_[i_ + 1] - temps_[i_]);
  }

 private:
  enum class Kind { constant, ramp, table };

  void readCsv(const std::string& path) {
    requireRegularFile(path, "temperature table");
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    if (line.rfind("t,temp", 0) != 0)
      throw InputError(path + ":1: expected the header \"t,temp\" (s, degC), got \"" +
                       limits::echo(line) + "\"");
    int row = 1;
    while (std::getline(in, line)) {
      ++row;
      if (line.empty()) continue;
      double t = NAN, c = NAN;
      char comma = 0;
      std::istringstream ss(line);
      if (!(ss >> t >> comma >> c) || comma != ',' || !std::isfinite(t) || !std::isfinite(c))
        throw InputError(path + ":" + std::to_string(row) + ": expected \"t,temp\" numbers, got \"" +
                         limits::echo(line) + "\"");
      if (!ts_.empty() && !(t > ts_.back()))
        throw InputError(path + ":" + std::to_string(row) + ": times must increase");
      ts_.push_back(t);
      temps_.push_back(c + kZeroCelsius);
    }
    if (ts_.empty()) throw InputError(path + ": no temperature rows");
  }

  Kind kind_ = Kind::constant;
  double duration_;
  double t0_ = NAN, t1_ = NAN;  // [K]
  std::vector<double> ts_, temps_;
  mutable std::size_t i_ = 0;
};

struct SynthOptions {
  std::string model, output, temperature = "25 degC", latitude = "45 deg", height = "0 m",
                           attitude = "0 deg, 0 deg, 0 deg";
  double rate = 0, duration = 0;
  std::uint64_t seed = 0, run = 0;
};

nav::Vec3 parseAttitude(const std::string& text) {
  nav::Vec3 rpy;
  std::stringstream ss(text);
  std::string part;
  int i = 0;
  while (std::getline(ss, part, ',')) {
    if (i == 3) break;
    std::string p = part;
    // A plain number is read as degrees: the README's examples write "0,0,90".
    Quantity q = parseQuantity(p);
    if (q.dim == Dimension::none()) q.si *= M_PI / 180.0;
    else if (q.dim != Dimension::angle())
      throw InputError("--attitude: \"" + p + "\" is not an angle");
    rpy[i++] = q.si;
  }
  if (i != 3 || std::getline(ss, part, ','))
    throw InputError("--attitude: expected roll,pitch,yaw (e.g. \"0,0,90\" deg or \"0 deg,2 deg,90 deg\"), got \"" +
                     text + "\"");
  return rpy;
}

char* put(char* p, char* end, double v, int precision) {
  auto r = std::to_chars(p, end, v, std::chars_format::general, precision);
  return r.ptr;
}

int runSynth(const SynthOptions& o) {
  if (!(o.rate >= limits::kMinRate && o.rate <= limits::kMaxRate))
    throw InputError("--rate must be from " + limits::fmt(limits::kMinRate) + " to " +
                     limits::fmt(limits::kMaxRate) + " Hz");
  if (!(std::isfinite(o.duration) && o.duration > 0)) throw InputError("--duration must be positive");
  if (limits::tooManySamples(o.duration, o.rate))
    throw InputError("--duration " + limits::fmt(o.duration) + " s at " + limits::fmt(o.rate) +
                     " Hz is more than " + limits::fmt(limits::kMaxSamples) +
                     " samples (docs/limits.md)");
  const auto model = errormodels::ImuErrorModel::load(o.model);
  const double lat = parseQuantityAs(o.latitude, Dimension::angle());
  if (!(std::fabs(lat) <= M_PI / 2)) throw InputError("--latitude must be within ±90 deg");
  const double h = parseQuantityAs(o.height, Dimension::length());
  const nav::Vec3 rpy = parseAttitude(o.attitude);
  const TemperatureProfile temperature(o.temperature, o.duration);

  // At rest on the rotating Earth: omega_ib_b = C_bn omega_ie_n, f_b = -C_bn g_n (normal gravity,
  // gravitation + centrifugal, GeographicLib via nav::Earth).
  const nav::Earth earth;
  const nav::Mat3 C_bn = nav::dcmFromEuler(rpy).transpose();
  const nav::Vec3 omega_ib_b = C_bn * earth.omega_ie_n(lat);
  const nav::Vec3 f_b = -(C_bn * earth.gravity_n(lat, h));

  auto corruptor = model.instantiate(o.rate, {o.seed, o.run});
  const long long n = std::llround(o.duration * o.rate);
  const double dt = 1.0 / o.rate;

  // Written to a temporary beside the target, renamed at the end: never a half-written file.
  const std::string tmp = o.output + ".tmp" + std::to_string(::getpid());
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw InputError("cannot write " + tmp);
  try {
    std::fputs("t,gx,gy,gz,ax,ay,az,temp\n", f);
    std::vector<char> buf(1 << 16);
    std::size_t used = 0;
    for (long long k = 1; k <= n; ++k) {
      nav::ImuSample s;
      s.t = double(k) * dt;
      s.dt = dt;
      s.dtheta_b = omega_ib_b * dt;
      s.dv_b = f_b * dt;
      const double T = temperature.at(s.t - 0.5 * dt);  // mid-interval [K]
      corruptor->corrupt(s, T);
      if (used + 256 > buf.size()) {
        if (std::fwrite(buf.data(), 1, used, f) != used) throw InputError("write error on " + tmp);
        used = 0;
      }
      char* p = buf.data() + used;
      char* end = buf.data() + buf.size();
      p = put(p, end, s.t, 12);
      for (int i = 0; i < 3; ++i) *p++ = ',', p = put(p, end, s.dtheta_b[i] / dt, 12);
      for (int i = 0; i < 3; ++i) *p++ = ',', p = put(p, end, s.dv_b[i] / dt, 12);
      *p++ = ',';
      p = put(p, end, T - kZeroCelsius, 8);
      *p++ = '\n';
      used = std::size_t(p - buf.data());
    }
    if (std::fwrite(buf.data(), 1, used, f) != used || std::fclose(f) != 0) {
      f = nullptr;
      throw InputError("write error on " + tmp);
    }
    f = nullptr;
    if (std::rename(tmp.c_str(), o.output.c_str()) != 0)
      throw InputError("cannot rename " + tmp + " to " + o.output);
  } catch (...) {
    if (f) std::fclose(f);
    std::remove(tmp.c_str());
    throw;
  }
  std::printf("wrote %s: %lld samples at %g Hz, model %s (%zu effects), seed %llu run %llu\n",
              o.output.c_str(), n, o.rate, model.source().c_str(), model.effectNames().size(),
              (unsigned long long)o.seed, (unsigned long long)o.run);
  return 0;
}

}  // namespace

void addSynthCommand(CLI::App& app, Action& action) {
  auto o = std::make_shared<SynthOptions>();
  CLI::App* c = app.add_subcommand(
      "synth", "write a static IMU record (CSV t,gx,gy,gz,ax,ay,az,temp; s, rad/s, m/s^2, degC) "
               "with Earth rate, gravity and the errors of MODEL");
  c->add_option("model", o->model, "error model file (YAML)")->required();
  c->add_option("--rate", o->rate, "IMU output rate [Hz]")->required();
  c->add_option("--duration", o->duration, "record length [s]")->required();
  c->add_option("--seed", o->seed, "seed of the random streams (default 0)");
  c->add_option("--run", o->run, "run index: the stream of run k of a batch (default 0)");
  c->add_option("--temperature", o->temperature,
                "sensor temperature: \"25 degC\" (default), a ramp \"20 degC..45 degC\" over the "
                "record, or a CSV file t,temp (s, degC)");
  c->add_option("--latitude", o->latitude, "geodetic latitude (default \"45 deg\")");
  c->add_option("--height", o->height, "height above the ellipsoid (default \"0 m\")");
  c->add_option("--attitude", o->attitude,
                "roll,pitch,yaw of the body in NED (plain numbers are degrees; default 0,0,0)");
  c->add_option("-o,--output", o->output, "output CSV file")->required();
  c->callback([o, &action] { action = [o] { return runSynth(*o); }; });
}

}  // namespace sinsim::cli
