#include "errormodels/fit/model_writer.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "common/error.hpp"
#include "common/units.hpp"

namespace sinsim::errormodels::fit {

namespace {

// Output units per sensor and quantity; the factor comes from the same parser that reads them.
struct Units {
  const char* level;       // signal: sigma, B
  const char* density;     // signal * sqrt(time): N
  const char* walk;        // signal / sqrt(time): K
  const char* increment;   // signal * time: quantization LSB
  const char* slope;       // signal / time: ramp
};
const Units& unitsFor(SensorSignal s) {
  static const Units gyro{"deg/s", "deg/sqrt(h)", "deg/h/sqrt(h)", "deg", "deg/h^2"};
  static const Units accel{"mg", "m/s/sqrt(h)", "m/s^2/sqrt(h)", "m/s", "m/s^3"};
  return s == SensorSignal::Gyro ? gyro : accel;
}

// "<value in unit> <unit>" with 9 significant digits (relative rounding <= 5e-9).
std::string q(double si, const char* unit) {
  const double factor = parseUnit(unit).si;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g %s", si / factor, unit);
  return buf;
}

std::string num(double v, int digits = 10) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string sensorName(SensorSignal s) { return s == SensorSignal::Gyro ? "gyro" : "accel"; }

void writeAr(std::ostringstream& out, const ArFit& ar, double rate, const Units& u,
             const std::optional<OrderSelection>& orders, const std::string& what) {
  if (!(std::isfinite(rate) && rate > 0.0))
    throw InputError("model writer: " + what + ": the AR rate must be a positive frequency");
  out << "    # AR(" << ar.order << ") by " << toString(ar.method) << ", N = " << ar.n
      << " samples at " << num(rate, 7) << " Hz, mean removed " << num(ar.mean, 7)
      << " (SI). sigma = sqrt(E), E = " << num(ar.drivingVariance, 7) << " +- "
      << num(ar.drivingVarianceStdError, 2) << " (SI^2)\n";
  out << "    # 1-sigma of a1..a" << ar.order << " (sigma^2 Gamma^-1 / N):";
  for (double s : ar.stdError) out << ' ' << num(s, 3);
  out << "\n    # largest pole " << num(arMaxPoleMagnitude(ar.a), 6) << "\n";
  if (orders) {
    out << "    # order criteria: AIC -> " << orders->aicOrder << ", MDL -> " << orders->mdlOrder
        << ", FPE -> " << orders->fpeOrder;
    if (orders->paperOrder)
      out << ", paper's rule -> " << *orders->paperOrder << " (T_c "
          << num(*orders->correlationTime * 1e3, 4) << " ms)";
    out << "; selected " << orders->selectedOrder << " by " << toString(orders->selectedBy) << "\n";
  }
  out << "    - {type: ar, a: [";
  for (std::size_t i = 1; i < ar.a.size(); ++i) out << (i > 1 ? ", " : "") << num(ar.a[i], 10);
  out << "], sigma: " << q(std::sqrt(ar.drivingVariance), u.level) << ", rate: " << num(rate, 10)
      << " Hz}\n";
}

void writeAllanTerm(std::ostringstream& out, const AllanFit& fit, AllanTermKind kind,
                    const Units& u) {
  const AllanTerm& t = fit.term(kind);
  if (!t.enabled) return;
  const char* unit = nullptr;
  double scale = 1.0;  // written value = scale * t.value (SI)
  switch (kind) {
    case AllanTermKind::Quantization: unit = u.increment; scale = std::sqrt(12.0); break;
    case AllanTermKind::White: unit = u.density; break;
    case AllanTermKind::BiasInstability: unit = u.level; break;
    case AllanTermKind::RandomWalk: unit = u.walk; break;
    case AllanTermKind::Ramp: unit = u.slope; break;
  }
  if (!t.detected) {
    out << "    # " << toString(kind) << ": not supported by the data, upper bound "
        << q(scale * t.upperBound, unit) << (kind == AllanTermKind::Quantization ? " (lsb)" : "")
        << "\n";
    return;
  }
  out << "    # " << toString(kind) << " +- " << q(scale * t.stdError, unit) << " (1 sigma)\n";
  switch (kind) {
    case AllanTermKind::Quantization:
      out << "    - {type: quantization, lsb: " << q(scale * t.value, unit) << "}\n";
      break;
    case AllanTermKind::White:
      out << "    - {type: white, density: " << q(t.value, unit) << "}\n";
      break;
    case AllanTermKind::BiasInstability:
      out << "    - {type: bias_instability, B: " << q(t.value, unit) << ", tau_range: ["
          << num(fit.tau.front(), 6) << " s, " << num(fit.tau.back(), 6) << " s]}\n";
      break;
    case AllanTermKind::RandomWalk:
      out << "    - {type: random_walk, K: " << q(t.value, unit) << "}\n";
      break;
    case AllanTermKind::Ramp:
      out << "    - {type: ramp, slope: " << q(t.value, unit) << "}\n";
      break;
  }
}

/// The latent fit's terms, each with its 1-sigma as a comment (latent_fit.hpp).
void writeLatent(std::ostringstream& out, const LatentFit& f, const Units& u) {
  const double rate = 1.0 / f.sampleInterval;
  out << "    # composite latent-process fit (GLS on the octave Allan variance, tau "
      << num(f.tau.front(), 4) << ".." << num(f.tau.back(), 6) << " s): " << f.terms.name()
      << "; chi2 " << num(f.chi2, 4) << " / " << f.dof << " dof (p = " << num(f.pValue, 3) << ")";
  if (const LatentCandidate* r = f.runnerUp())
    out << "; runner-up " << r->terms.name() << " (score +" << num(r->score - f.candidates.front().score, 3) << ")";
  out << "\n";
  for (const auto& w : f.warnings) out << "    # WARNING: " << w << "\n";
  auto sd = [&](const std::string& name, const char* unit, double scale = 1.0) {
    return q(scale * f.parameter(name).stdError, unit);
  };
  const LatentModel& m = f.model;
  if (m.quantization > 0.0) {
    out << "    # quantization lsb +- " << sd("quantization", u.increment, std::sqrt(12.0)) << " (1 sigma)\n";
    out << "    - {type: quantization, lsb: " << q(std::sqrt(12.0) * m.quantization, u.increment) << "}\n";
  }
  if (m.white > 0.0) {
    out << "    # white +- " << sd("white", u.density) << " (1 sigma)\n";
    out << "    - {type: white, density: " << q(m.white, u.density) << "}\n";
  }
  for (std::size_t g = 0; g < m.gm.size(); ++g) {
    const std::string n = "gm" + std::to_string(g + 1);
    out << "    # " << n << ": sigma +- " << sd(n + ".sigma", u.level) << ", tau +- "
        << num(f.parameter(n + ".tau").stdError, 4) << " s (1 sigma)\n";
    out << "    - {type: gauss_markov, sigma: " << q(m.gm[g].sigma, u.level) << ", tau: "
        << num(m.gm[g].tau, 7) << " s, rate: " << num(rate, 10) << " Hz}\n";
  }
  if (m.flicker > 0.0) {
    out << "    # flicker +- " << sd("flicker", u.level) << " (1 sigma)\n";
    out << "    - {type: bias_instability, B: " << q(m.flicker, u.level) << ", tau_range: ["
        << num(f.tau.front(), 6) << " s, " << num(f.tau.back(), 6) << " s]}\n";
  }
  if (m.randomWalk > 0.0) {
    out << "    # random_walk +- " << sd("random_walk", u.walk) << " (1 sigma)\n";
    out << "    - {type: random_walk, K: " << q(m.randomWalk, u.walk) << "}\n";
  }
  if (m.drift > 0.0) {
    out << "    # drift (ramp) +- " << sd("drift", u.slope) << " (1 sigma; the Allan variance does not give its sign)\n";
    out << "    - {type: ramp, slope: " << q(m.drift, u.slope) << "}\n";
  }
}

}  // namespace

std::string modelYaml(const std::vector<AxisFitResult>& axes, const ModelProvenance& p) {
  std::ostringstream out;
  out << "# Error model fitted by sinsim (errormodels/fit).\n";
  if (!p.dataFile.empty()) out << "# data: " << p.dataFile << "\n";
  if (p.rate > 0.0) out << "# rate: " << num(p.rate, 10) << " Hz\n";
  if (p.duration > 0.0) out << "# duration: " << num(p.duration, 10) << " s\n";
  if (!p.method.empty()) out << "# method: " << p.method << "\n";
  for (const auto& n : p.notes) out << "# " << n << "\n";
  std::string desc = p.description.empty() ? "fitted error model" : p.description;
  for (char& c : desc)
    if (c == '\n' || c == '"') c = ' ';
  out << "description: \"" << desc << "\"\n";

  for (SensorSignal sensor : {SensorSignal::Gyro, SensorSignal::Accel}) {
    bool any = false;
    for (const auto& ax : axes) any = any || ax.sensor == sensor;
    if (!any) continue;
    out << sensorName(sensor) << ":\n";
    const Units& u = unitsFor(sensor);
    std::map<std::string, int> seen;
    for (const auto& ax : axes) {
      if (ax.sensor != sensor) continue;
      if (ax.axis != "x" && ax.axis != "y" && ax.axis != "z" && ax.axis != "all")
        throw InputError("model writer: axis must be x, y, z or all, got \"" + ax.axis + "\"");
      const std::string what = sensorName(sensor) + "." + ax.axis;
      if (seen[ax.axis]++)
        throw InputError("model writer: " + what + " given twice");
      out << "  " << ax.axis << ":\n";
      for (const auto& n : ax.notes) out << "    # " << n << "\n";
      const std::size_t before = out.str().size();
      if (ax.composite) {
        const auto& c = *ax.composite;
        out << "    # composite AR + random walk: K from the Allan curve (tau >= "
            << num(c.allan.tau.front(), 4) << " s), random-walk level removed by an RTS "
            << "smoother (T_s " << num(c.smootherTimeConstant, 4) << " s vs AR T_c "
            << num(c.arCorrelationTime * 1e3, 4) << " ms"
            << (c.separated ? "" : "; NOT well separated") << ")\n";
        writeAr(out, c.ar.fit, ax.arRate, u, c.ar, what);
        if (c.randomWalkDetected) {
          out << "    # random_walk +- " << q(c.randomWalk.stdError, u.walk) << " (1 sigma)\n";
          out << "    - {type: random_walk, K: " << q(c.randomWalk.value, u.walk) << "}\n";
        } else {
          out << "    # random_walk: not detected, upper bound "
              << q(c.randomWalk.upperBound, u.walk) << "\n";
        }
      }
      if (ax.ar) writeAr(out, *ax.ar, ax.arRate, u, ax.arOrders, what);
      if (ax.gaussMarkov) {
        const auto& g = *ax.gaussMarkov;
        out << "    # first-order GM from the ACF (lags " << g.firstLag << ".." << g.lastLag
            << "): sigma +- " << q(g.sigmaStdError, u.level) << ", tau +- "
            << num(g.tauStdError, 4) << " s"
            << (g.bartlettCovariance ? " (Bartlett)" : " (LS residuals; underestimates)") << "\n";
        out << "    - {type: gauss_markov, sigma: " << q(g.sigma, u.level)
            << ", tau: " << num(g.tau, 7) << " s}\n";
      }
      if (ax.latent) writeLatent(out, *ax.latent, u);
      if (ax.allan) {
        out << "    # Allan-term fit: " << ax.allan->pointsUsed << " points, tau "
            << num(ax.allan->tau.front(), 4) << ".." << num(ax.allan->tau.back(), 6)
            << " s, chi2 " << num(ax.allan->chi2, 4) << " / " << ax.allan->dof << " dof"
            << (ax.allan->correlated ? ", correlated points (GLS)" : ", independent points")
            << "\n";
        for (std::size_t j = 0; j < kAllanTermCount; ++j)
          if (ax.allanWrite[j]) writeAllanTerm(out, *ax.allan, static_cast<AllanTermKind>(j), u);
      }
      if (out.str().find("- {type:", before) == std::string::npos)
        out << "    []\n";  // an axis without effects stays valid YAML (an empty list)
    }
  }
  return out.str();
}

void writeModelFile(const std::string& path, const std::vector<AxisFitResult>& axes,
                    const ModelProvenance& provenance) {
  const std::string text = modelYaml(axes, provenance);
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) throw Error("cannot write model file " + tmp);
    f << text;
    f.flush();
    if (!f) {
      std::remove(tmp.c_str());
      throw Error("cannot write model file " + tmp);
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw Error("cannot move model file into place: " + path);
  }
}

}  // namespace sinsim::errormodels::fit
