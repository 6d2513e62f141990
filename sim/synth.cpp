#include "sim/synth.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/atomic_file.hpp"
#include "common/constants.hpp"
#include "common/error.hpp"
#include "common/limits.hpp"
#include "common/progress.hpp"
#include "common/units.hpp"
#include "nav/attitude.hpp"
#include "nav/earth.hpp"
#include "sim/output.hpp"

namespace sinsim::sim {
namespace {


char* put(char* p, char* end, double v, int precision) {
  return std::to_chars(p, end, v, std::chars_format::general, precision).ptr;
}

}  // namespace

long long writeStaticRecord(const errormodels::ImuErrorModel& model, const StaticRecordSpec& o,
                            const TemperatureProfile& temperature, const std::string& path) {
  if (!(o.rate >= limits::kMinRate && o.rate <= limits::kMaxRate))
    throw InputError("--rate must be from " + limits::fmt(limits::kMinRate) + " to " +
                     limits::fmt(limits::kMaxRate) + " Hz");
  if (!(std::isfinite(o.duration) && o.duration > 0)) throw InputError("--duration must be positive");
  if (limits::tooManySamples(o.duration, o.rate))
    throw InputError("--duration " + limits::fmt(o.duration) + " s at " + limits::fmt(o.rate) +
                     " Hz is more than " + limits::fmt(limits::kMaxSamples) +
                     " samples (docs/limits.md)");
  if (!(std::fabs(o.lat) <= M_PI / 2)) throw InputError("--latitude must be within ±90 deg");
  if (!(o.h >= limits::kMinHeight && o.h <= limits::kMaxHeight))  // -1e7 m wrote az = +30 m/s^2
    throw InputError("--height " + limits::fmt(o.h) + " m is outside [" + limits::fmt(limits::kMinHeight) + ", " +
                     limits::fmt(limits::kMaxHeight) + "] m (docs/limits.md)");
  if (!(o.rpy.array().isFinite().all())) throw InputError("--attitude must be finite");

  const nav::Earth earth;
  const nav::Mat3 C_bn = nav::dcmFromEuler(o.rpy).transpose();
  const nav::Vec3 omega_ib_b = C_bn * earth.omega_ie_n(o.lat);
  const nav::Vec3 f_b = -(C_bn * earth.gravity_n(o.lat, o.h));

  auto corruptor = model.instantiate(o.rate, o.key);
  const long long n = std::llround(o.duration * o.rate);
  const double dt = 1.0 / o.rate;

  requireWritableTarget(path);  // an output file's folder is not created (docs/limits.md)
  const std::filesystem::path target(path);
  OutputFiles out(target.has_parent_path() ? target.parent_path().string() : ".");
  std::FILE* f = out.open(target.filename().string());
  // Units in the header: any reader (ours included) converts from them.
  std::fputs("t [s],gx [rad/s],gy [rad/s],gz [rad/s],ax [m/s^2],ay [m/s^2],az [m/s^2],temp [degC]\n", f);
  std::vector<char> buf(1 << 16);
  std::size_t used = 0;
  auto flush = [&] {
    if (std::fwrite(buf.data(), 1, used, f) != used) throw Error(writeErrorMessage(path, errno));
    used = 0;
  };
  for (long long k = 1; k <= n; ++k) {
    // An interruption unwinds through `out`, which removes the unfinished file.
    if ((k & 0xffff) == 0) progress::checkpoint("synthesising", std::uint64_t(k), std::uint64_t(n));
    nav::ImuSample s;
    s.t = double(k) * dt;
    s.dt = dt;
    s.dtheta_b = omega_ib_b * dt;
    s.dv_b = f_b * dt;
    const double T = temperature.at(s.t - 0.5 * dt);  // mid-interval [K]
    corruptor->corrupt(s, T);
    if (used + 256 > buf.size()) flush();
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
  flush();
  out.commit();
  return n;
}

}  // namespace sinsim::sim
