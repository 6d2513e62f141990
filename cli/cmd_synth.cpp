// `sinsim synth MODEL --rate HZ --duration S -o FILE.csv`: a static IMU record with a known error
// model (sim/synth.hpp) — test data with known truth for the identification path.
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "cli/commands.hpp"
#include "cli/terminal.hpp"
#include "common/constants.hpp"
#include "common/error.hpp"
#include "common/units.hpp"
#include "errormodels/imu_model.hpp"
#include "sim/synth.hpp"

namespace sinsim::cli {
namespace {

struct SynthOptions {
  std::string model, output, temperature = "25 degC", latitude = "45 deg", height = "0 m",
                           attitude = "0 deg, 0 deg, 0 deg", duration;
  double rate = 0;
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
    if (q.dim == Dimension::none()) q.si *= kRadPerDeg;
    else if (q.dim != Dimension::angle())
      throw InputError("--attitude: \"" + p + "\" is not an angle");
    rpy[i++] = q.si;
  }
  if (i != 3 || std::getline(ss, part, ','))
    throw InputError("--attitude: expected roll,pitch,yaw (e.g. \"0,0,90\" deg or \"0 deg,2 deg,90 deg\"), got \"" +
                     text + "\"");
  return rpy;
}

int runSynth(const SynthOptions& o) {
  const auto model = errormodels::ImuErrorModel::load(o.model);
  sim::StaticRecordSpec spec;
  spec.rate = o.rate;
  spec.duration = parseDuration(o.duration, "--duration");
  spec.key = {o.seed, o.run};
  spec.lat = parseOptionQuantity(o.latitude, Dimension::angle(), "--latitude");
  spec.h = parseOptionQuantity(o.height, Dimension::length(), "--height");
  spec.rpy = parseAttitude(o.attitude);
  const sim::TemperatureProfile temperature = sim::temperatureFromText(o.temperature, spec.duration);
  const long long n = sim::writeStaticRecord(model, spec, temperature, o.output);
  endProgressLine();
  std::printf("wrote %s: %lld samples at %g Hz, model %s (%zu effects), seed %llu run %llu\n",
              o.output.c_str(), n, o.rate, model.source().c_str(), model.effectNames().size(),
              (unsigned long long)o.seed, (unsigned long long)o.run);
  return 0;
}

}  // namespace

void addSynthCommand(CLI::App& app, Action& action) {
  auto o = std::make_shared<SynthOptions>();
  CLI::App* c = app.add_subcommand(
      "synth", "write a static IMU record (CSV t [s], gx gy gz [rad/s], ax ay az [m/s^2], temp [degC]) "
               "with Earth rate, gravity and the errors of MODEL");
  c->add_option("model", o->model, "error model file (YAML)")->required();
  c->add_option("--rate", o->rate, "IMU output rate [Hz]")->required();
  c->add_option("--duration", o->duration, "record length, e.g. \"20 min\" (a plain number is seconds)")->required();
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
