// The diagnosis (diagnose.hpp): comparison, failing ranges, forward selection of the missing
// effects, the improved model, JSON and the terminal table.
#include "errormodels/diagnose/diagnose.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <unistd.h>

#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

#include "common/error.hpp"
#include "common/limits.hpp"
#include "common/read_file.hpp"
#include "common/units.hpp"
#include "errormodels/diagnose/internal.hpp"
#include "errormodels/fit/allan_fit.hpp"
#include "errormodels/fit/ar_fit.hpp"
#include "errormodels/fit/composite_fit.hpp"
#include "errormodels/stats/special.hpp"
#include "errormodels/stats/spectrum.hpp"

namespace sinsim::errormodels::diagnose {

using namespace detail;

ModelText ModelText::load(const std::string& path) {
  return {readRegularFile(path, limits::kMaxYamlBytes, "model file"), path};
}

const std::vector<std::string>& detectableEffects() {
  static const std::vector<std::string> e = {"quantization", "random_walk", "ramp",
                                             "bias_instability", "sinusoid", "temperature",
                                             "warmup", "outliers"};
  return e;
}

AddRequest AddRequest::parse(const std::string& text) {
  AddRequest r;
  const auto colon = text.find(':');
  r.effect = text.substr(0, colon);
  if (colon != std::string::npos) {
    r.channel = text.substr(colon + 1);
    channelIndex(r.channel);
  }
  const auto& known = detectableEffects();
  if (r.effect != "found" && std::find(known.begin(), known.end(), r.effect) == known.end()) {
    std::string list;
    for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
    throw InputError("--add " + text + ": unknown effect \"" + r.effect + "\" (the diagnosis can add: " +
                     list + "; or \"found\": every reported finding)");
  }
  return r;
}

bool AxisDiagnosis::fits(double threshold) const {
  for (const auto& f : findings)
    if (f.reported && f.score >= threshold) return false;
  // and the Allan chi-square below its 0.999 quantile
  return chi2Points == 0 || chi2 < chiSquareQuantile(0.999, double(chi2Points));
}

const AxisDiagnosis& Diagnosis::axis(const std::string& channel) const {
  for (const auto& a : axes)
    if (a.channel == channel) return a;
  throw InputError("channel " + channel + " was not diagnosed");
}

void writeFileAtomic(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw InputError("cannot write " + path + " (folder missing or not writable)");
    out << text;
    out.flush();
    if (!out) {
      out.close();
      std::remove(tmp.c_str());
      throw Error("write error on " + tmp);
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw Error("cannot rename " + tmp + " to " + path);
  }
}

Record simulateRecord(const ModelText& model, double rate, std::size_t samples, std::uint64_t seed,
                      std::uint64_t run, const std::vector<double>& ideal,
                      const std::vector<double>& temperatureK) {
  if (ideal.size() != 6) throw InputError("simulateRecord: 6 ideal values expected");
  if (!temperatureK.empty() && temperatureK.size() != samples)
    throw InputError("simulateRecord: one temperature per sample expected");
  const auto m = ImuErrorModel::fromString(model.text, model.name);
  std::array<std::vector<double>, 6> out;
  simulate(m, rate, samples, ideal, temperatureK, seed, run, {0, 1, 2, 3, 4, 5}, out);
  Record r;
  r.source = model.name + " (simulated, seed " + std::to_string(seed) + ")";
  r.rate_hz = rate;
  r.rows = samples;
  for (int a = 0; a < 3; ++a) r.gyro[a] = std::move(out[a]), r.accel[a] = std::move(out[3 + a]);
  r.temperature = temperatureK;
  return r;
}

namespace {

/// Central interval of a variance estimate with nu EDF around its mean: mean chi2_q(nu) / nu.
double chi2Factor(double p, double nu) {
  if (!(nu < 1e6)) {  // the chi-square law is normal to 1e-3 here: mean (1 + z sqrt(2/nu))
    const double z = fit::normalQuantileTwoSided(std::fabs(2 * p - 1)) * (p < 0.5 ? -1 : 1);
    return std::max(0.0, 1 + z * std::sqrt(2 / nu));
  }
  return chiSquareQuantile(p, nu) / nu;
}

struct Moments {
  double mean = 0, var = 0;
};
Moments moments(const std::vector<double>& v) {
  Moments m;
  for (double x : v) m.mean += x;
  m.mean /= double(v.size());
  for (double x : v) m.var += (x - m.mean) * (x - m.mean);
  m.var /= double(v.size() - 1);
  return m;
}

/// Band of a variance-like statistic from its realisations (chi-square with nu = 2 mean^2/var).
void chiBand(const std::vector<double>& real, double level, double& model, double& lo, double& hi) {
  const auto m = moments(real);
  model = m.mean;
  const double nu = m.var > 0 ? 2 * m.mean * m.mean / m.var : INFINITY;
  lo = m.mean * chi2Factor((1 - level) / 2, nu);
  hi = m.mean * chi2Factor((1 + level) / 2, nu);
}

std::vector<FailRange> failRanges(const Comparison& c, const std::string& stat) {
  std::vector<FailRange> out;
  for (std::size_t i = 0; i < c.x.size();) {
    if (c.outside[i] == 0) {
      ++i;
      continue;
    }
    FailRange f;
    f.statistic = stat;
    f.direction = c.outside[i];
    f.from = c.x[i];
    double worst = 0;
    std::size_t j = i;
    for (; j < c.x.size() && c.outside[j] == f.direction; ++j) {
      const double r = c.meas[j] / c.model[j];
      const double far = std::fabs(std::log(r));
      if (far > worst) worst = far, f.worstRatio = r;
      f.to = c.x[j];
      ++f.points;
    }
    out.push_back(f);
    i = j;
  }
  return out;
}

/// Narrow-line test on the raw Welch PSD: each bin against the median of its neighbourhood
/// (bins k-12..k-3 and k+3..k+12; the Hann main lobe is +-2 bins), chi-square with the Welch EDF
/// nu = 2 K / 1.056 (K segments, 50 % overlap Hann: Welch 1967, Percival & Walden 1993 eq. 292b),
/// Bonferroni over the bins tested. Returns z (two-sided Gaussian equivalent) and the frequency.
void psdLineTest(const PowerSpectrum& p, double& z, double& freq) {
  z = 0, freq = 0;
  const std::size_t nbins = p.psd.size();
  if (nbins < 40) return;
  const double nu = 2.0 * double(p.segments) / 1.056;
  const double medFactor = std::pow(1 - 2 / (9 * nu), 3);  // median of chi2_nu / nu (Wilson-Hilferty)
  double bestP = 1.0;
  std::size_t tested = 0;
  for (std::size_t k = 3; k + 3 < nbins; ++k) {
    std::vector<double> nb;
    for (std::ptrdiff_t d = -12; d <= 12; ++d) {
      if (std::abs(d) < 3) continue;
      const std::ptrdiff_t j = std::ptrdiff_t(k) + d;
      if (j >= 1 && j < std::ptrdiff_t(nbins)) nb.push_back(p.psd[std::size_t(j)]);
    }
    std::nth_element(nb.begin(), nb.begin() + std::ptrdiff_t(nb.size() / 2), nb.end());
    const double ref = nb[nb.size() / 2] / medFactor;
    if (!(ref > 0)) continue;
    ++tested;
    const double ratio = p.psd[k] / ref;
    if (ratio < 4) continue;
    const double pk = regularizedGammaQ(nu / 2, ratio * nu / 2);  // P(chi2_nu / nu > ratio)
    if (pk < bestP) bestP = pk, freq = p.f[k];
  }
  if (freq <= 0) return;
  const double pAll = std::min(1.0, double(tested) * bestP);
  // z with P(|Z| > z) = pAll
  if (pAll >= 1) {
    freq = 0;
    return;
  }
  double lo = 0, hi = 40;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (std::erfc(mid / std::sqrt(2.0)) > pAll) lo = mid;
    else hi = mid;
  }
  z = pAll > 0 ? hi : 40.0;
}

/// The `ar` effect of a channel at the record's rate, if the model has exactly one.
std::optional<std::vector<double>> arOfChannel(const std::string& text, int channel, double rate) {
  YAML::Node root = YAML::Load(text);
  YAML::Node sensor = root[sensorName(channel)];
  if (!sensor || !sensor.IsMap()) return std::nullopt;
  std::optional<std::vector<double>> found;
  int count = 0;
  for (const char* list : {"all", axisName(channel)}) {
    YAML::Node l = sensor[list];
    if (!l || !l.IsSequence()) continue;
    for (const auto& e : l) {
      if (!e.IsMap() || !e["type"] || e["type"].as<std::string>() != "ar") continue;
      ++count;
      try {
        const double r = parseQuantityAs(e["rate"].as<std::string>(), Dimension::frequency());
        if (std::fabs(r - rate) > 1e-6 * rate) continue;
        std::vector<double> a{1.0};
        for (const auto& v : e["a"]) a.push_back(v.as<double>());
        found = a;
      } catch (const std::exception&) {
      }
    }
  }
  if (count != 1) return std::nullopt;
  return found;
}

LjungBox ljungBox(const std::vector<double>& y, const std::vector<double>& a, std::size_t h) {
  const std::size_t p = a.size() - 1, N = y.size();
  double mean = 0;
  for (double v : y) mean += v;
  mean /= double(N);
  std::vector<double> e(N - p);
  for (std::size_t n = p; n < N; ++n) {
    double v = 0;
    for (std::size_t i = 0; i <= p; ++i) v += a[i] * (y[n - i] - mean);
    e[n - p] = v;
  }
  const std::size_t M = e.size();
  double em = 0;
  for (double v : e) em += v;
  em /= double(M);
  for (double& v : e) v -= em;
  double r0 = 0;
  for (double v : e) r0 += v * v;
  LjungBox lb;
  lb.lags = h;
  lb.dof = h > p ? h - p : 1;
  double Q = 0;
  for (std::size_t k = 1; k <= h; ++k) {  // Ljung & Box 1978: Q = N (N+2) sum r_k^2 / (N - k)
    double rk = 0;
    for (std::size_t n = k; n < M; ++n) rk += e[n] * e[n - k];
    rk /= r0;
    Q += rk * rk / double(M - k);
  }
  lb.Q = double(M) * double(M + 2) * Q;
  lb.pValue = regularizedGammaQ(double(lb.dof) / 2, lb.Q / 2);
  return lb;
}

/// Base AR refitted with a lattice quantization taken out of its autocovariance: Yule-Walker on
/// r_y(k) - r_q(k), r_q the rounding noise's autocovariance [SI^2]: per-sample rounding
/// r_q(0) = q^2/12; carried remainder (rate error (d_{k-1} - d_k)/dt, d uniform) r_q(0) = q^2/6,
/// r_q(1) = -q^2/12 (q the rate LSB). Returns a = [1, a1..ap] and the driving variance.
bool arWithoutQuantization(const std::vector<double>& y, std::size_t order, double q, bool carry,
                           std::vector<double>& a, double& E) {
  double m = 0;
  for (double v : y) m += v;
  m /= double(y.size());
  std::vector<double> x(y.size());
  for (std::size_t k = 0; k < y.size(); ++k) x[k] = y[k] - m;
  auto r = fit::biasedAutocovariance(x, order);
  r[0] -= carry ? q * q / 6 : q * q / 12;
  if (carry && r.size() > 1) r[1] += q * q / 12;
  if (!(r[0] > 0)) return false;
  try {
    const auto f = fit::yuleWalkerFromAutocovariance(r, order, y.size());
    if (!(f.drivingVariance > 0) || fit::arMaxPoleMagnitude(f.a) >= 1) return false;
    a = f.a;
    E = f.drivingVariance;
    return true;
  } catch (const Error&) {
    return false;
  }
}

struct ChannelWork {
  std::vector<std::size_t> factors;
  int channel = 0;
  AxisDiagnosis d;
  AllanProblem prob;
  std::vector<Candidate> cands;
  std::vector<std::size_t> accepted;
  AllanSolution sol;
};

struct Run {
  Diagnosis d;
  std::vector<ChannelWork> work;
};

const std::vector<std::size_t>& setupFactors(const ChannelWork& w) { return w.factors; }

Run diagnoseRun(const Record& record, const ModelText& model, const DiagnoseOptions& o) {
  if (o.realisations < 8) throw InputError("at least 8 Monte Carlo realisations are needed");
  if (!(o.bandLevel > 0 && o.bandLevel < 1)) throw InputError("band level must be in (0, 1)");
  if (record.rows < 256) throw InputError(record.source + ": at least 256 samples are needed");
  std::vector<int> channels;
  if (o.channels.empty()) {
    for (int c = 0; c < 6; ++c)
      if (!channelData(record, c).empty()) channels.push_back(c);
  } else {
    for (const auto& name : o.channels) {
      const int c = channelIndex(name);
      if (channelData(record, c).empty()) throw InputError(record.source + " has no channel " + name);
      channels.push_back(c);
    }
  }
  if (channels.empty()) throw InputError(record.source + ": no gyro or accelerometer channel");
  const auto m = ImuErrorModel::fromString(model.text, model.name);
  if (m.needsTemperature() && record.temperature.empty())
    throw InputError("model " + model.name + " needs the sensor temperature, and " + record.source +
                     " has no temp column");
  const Setup setup = makeSetup(record.rate_hz, record.rows, o);
  const auto mc = monteCarlo(m, record, channels, setup, o);
  const std::size_t R = o.realisations, K = setup.factors.size();
  const double zAcf = fit::normalQuantileTwoSided(o.bandLevel);

  Run run;
  run.d.data = record.source;
  run.d.model = model.name;
  run.d.rate = record.rate_hz;
  run.d.samples = record.rows;
  run.d.realisations = R;
  run.d.threshold = o.threshold;
  run.d.bandLevel = o.bandLevel;
  for (std::size_t ci = 0; ci < channels.size(); ++ci) {
    const int c = channels[ci];
    const auto& y = channelData(record, c);
    const auto& real = mc.perChannel[ci];
    ChannelWork w;
    w.channel = c;
    w.factors = setup.factors;
    AxisDiagnosis& d = w.d;
    d.channel = kChannels[c];
    d.unit = unitsFor(c).level;
    d.unitFactor = parseUnit(d.unit).si;
    const SeriesStats meas = seriesStats(y, setup);

    // ADEV
    std::vector<double> tau(K);
    for (std::size_t k = 0; k < K; ++k) tau[k] = double(setup.factors[k]) / record.rate_hz;
    d.adev.x = tau;
    Eigen::MatrixXd logs(static_cast<Eigen::Index>(R), static_cast<Eigen::Index>(K));
    w.prob.L.resize(K), w.prob.mu.resize(K), w.prob.bias.resize(K);
    double sumsq = 0;
    std::size_t out = 0;
    for (std::size_t k = 0; k < K; ++k) {
      std::vector<double> a(R);
      for (std::size_t r = 0; r < R; ++r) a[r] = real[r].avar[k];
      double mu, lo, hi;
      chiBand(a, o.bandLevel, mu, lo, hi);
      mu = std::max(mu, 1e-300);
      const double mv = std::max(meas.avar[k], 1e-300);
      d.adev.meas.push_back(std::sqrt(mv));
      d.adev.model.push_back(std::sqrt(mu));
      d.adev.lo.push_back(std::sqrt(std::max(lo, 0.0)));
      d.adev.hi.push_back(std::sqrt(hi));
      const int side = mv > hi ? 1 : (mv < lo ? -1 : 0);
      d.adev.outside.push_back(side);
      out += side != 0;
      const double l10 = std::log10(std::sqrt(mv / mu));
      sumsq += l10 * l10;
      double lm = 0;
      for (std::size_t r = 0; r < R; ++r) {
        logs(Eigen::Index(r), Eigen::Index(k)) = std::log(std::max(a[r], 1e-300));
        lm += logs(Eigen::Index(r), Eigen::Index(k));
      }
      lm /= double(R);
      w.prob.L[k] = std::log(mv);
      w.prob.mu[k] = mu;
      w.prob.bias[k] = lm - std::log(mu);
    }
    d.misfitRaw = std::sqrt(sumsq / double(K));
    {
      double fl = 0;
      for (std::size_t r = 0; r < R; ++r)
        for (std::size_t k = 0; k < K; ++k) {
          const double l10 = (logs(Eigen::Index(r), Eigen::Index(k)) - std::log(w.prob.mu[k])) / (2 * std::log(10.0));
          fl += l10 * l10;
        }
      d.misfitFloor = std::sqrt(fl / double(R * K));
      d.misfit = std::sqrt(std::max(0.0, sumsq / double(K) - d.misfitFloor * d.misfitFloor));
    }
    d.fractionOutside = double(out) / double(K);
    // Covariance of ln AVAR: per-tau variances, correlation averaged along the octave diagonals
    // (the estimates at tau_i, tau_j depend mostly on tau_j / tau_i), eigenvalues floored, times
    // 1 + 1/R for the Monte Carlo mean's own error.
    {
      Eigen::MatrixXd X = logs.rowwise() - logs.colwise().mean();
      Eigen::MatrixXd C = X.transpose() * X / double(R - 1);
      Eigen::VectorXd sd = C.diagonal().cwiseMax(1e-12).cwiseSqrt();
      std::vector<double> rho(K, 0.0);
      for (std::size_t lag = 0; lag < K; ++lag) {
        double s = 0;
        for (std::size_t i = 0; i + lag < K; ++i)
          s += C(Eigen::Index(i), Eigen::Index(i + lag)) / (sd[Eigen::Index(i)] * sd[Eigen::Index(i + lag)]);
        rho[lag] = s / double(K - lag);
      }
      rho[0] = 1;
      Eigen::MatrixXd Cs(static_cast<Eigen::Index>(K), static_cast<Eigen::Index>(K));
      for (std::size_t i = 0; i < K; ++i)
        for (std::size_t j = 0; j < K; ++j)
          Cs(Eigen::Index(i), Eigen::Index(j)) =
              sd[Eigen::Index(i)] * sd[Eigen::Index(j)] * rho[i > j ? i - j : j - i] * (1 + 1.0 / double(R));
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Cs);
      Eigen::VectorXd ev = es.eigenvalues();
      const double floor = 1e-3 * ev.maxCoeff();
      Eigen::VectorXd inv = ev.cwiseMax(floor).cwiseInverse();
      w.prob.W = es.eigenvectors() * inv.asDiagonal() * es.eigenvectors().transpose();
    }
    {
      Eigen::VectorXd r(static_cast<Eigen::Index>(K));
      for (std::size_t k = 0; k < K; ++k)
        r[Eigen::Index(k)] = w.prob.L[k] - w.prob.bias[k] - std::log(w.prob.mu[k]);
      d.chi2 = r.dot(w.prob.W * r);
      d.chi2Points = K;
    }

    // PSD bands
    for (std::size_t b = 0; b < setup.psdBandFreq.size(); ++b) {
      std::vector<double> v(R);
      for (std::size_t r = 0; r < R; ++r) v[r] = real[r].psd[b];
      double mu, lo, hi;
      chiBand(v, o.bandLevel, mu, lo, hi);
      d.psd.x.push_back(setup.psdBandFreq[b]);
      d.psd.meas.push_back(meas.psd[b]);
      d.psd.model.push_back(mu);
      d.psd.lo.push_back(lo);
      d.psd.hi.push_back(hi);
      d.psd.outside.push_back(meas.psd[b] > hi ? 1 : (meas.psd[b] < lo ? -1 : 0));
    }
    // ACF
    for (std::size_t l = 0; l <= setup.acfLags; ++l) {
      std::vector<double> v(R);
      for (std::size_t r = 0; r < R; ++r) v[r] = real[r].acf[l];
      const auto mm = moments(v);
      const double half = zAcf * std::sqrt(mm.var * (1 + 1.0 / double(R)));
      d.acf.x.push_back(double(l) / record.rate_hz);
      d.acf.meas.push_back(meas.acf[l]);
      d.acf.model.push_back(mm.mean);
      d.acf.lo.push_back(mm.mean - half);
      d.acf.hi.push_back(mm.mean + half);
      d.acf.outside.push_back(meas.acf[l] > mm.mean + half ? 1 : (meas.acf[l] < mm.mean - half ? -1 : 0));
    }
    d.fails = failRanges(d.adev, "adev");
    for (auto& f : failRanges(d.psd, "psd")) d.fails.push_back(f);

    if (auto a = arOfChannel(model.text, c, record.rate_hz))
      if (y.size() > o.ljungBoxLags + a->size() + 10) d.ljungBox = ljungBox(y, *a, o.ljungBoxLags);

    // Candidates and the forward selection.
    WelchOptions wo;
    wo.segment_length = setup.psdSegment;
    const auto rawPsd = welchPsd(y, record.rate_hz, wo);
    double lineZ = 0, lineF = 0;
    psdLineTest(rawPsd, lineZ, lineF);
    std::vector<double> modelAvar = w.prob.mu;
    w.cands = buildCandidates(record, c, tau, setup, meas.avar, modelAvar, model.text, lineZ, lineF);
    w.sol = solveAllan(w.prob, {});
    std::vector<double> lastScore(w.cands.size(), 0.0), lastDchi(w.cands.size(), 0.0);
    std::vector<AllanSolution> lastSol(w.cands.size());
    for (;;) {
      std::set<std::string> taken;
      std::vector<const Candidate*> set;
      for (auto i : w.accepted) taken.insert(w.cands[i].effect), set.push_back(&w.cands[i]);
      std::ptrdiff_t best = -1;
      const auto currentAvar = modelAvarOf(w.prob, set, w.sol);
      for (std::size_t i = 0; i < w.cands.size(); ++i) {
        if (taken.count(w.cands[i].effect)) continue;
        auto trial = set;
        trial.push_back(&w.cands[i]);
        auto start = w.sol.theta;
        start.push_back(-1.0);
        lastSol[i] = solveAllan(w.prob, trial, start);
        lastDchi[i] = w.sol.chi2 - lastSol[i].chi2;
        double z = std::max(std::sqrt(std::max(0.0, lastDchi[i])), w.cands[i].zSpecial);
        if (w.cands[i].zConditional) z = std::max(z, w.cands[i].zConditional(currentAvar));
        lastScore[i] = std::min(40.0, z);
        if (best < 0 || lastScore[i] > lastScore[std::size_t(best)] ||
            (lastScore[i] == lastScore[std::size_t(best)] && lastDchi[i] > lastDchi[std::size_t(best)]))
          best = std::ptrdiff_t(i);
      }
      if (best < 0 || lastScore[std::size_t(best)] < o.threshold) break;
      Finding f;
      f.effect = w.cands[std::size_t(best)].effect;
      f.score = lastScore[std::size_t(best)];
      f.reported = true;
      w.accepted.push_back(std::size_t(best));
      w.sol = lastSol[std::size_t(best)];
      d.findings.push_back(f);
    }
    // Sizes of the reported ones from the final joint fit.
    for (std::size_t j = 0; j < w.accepted.size(); ++j) {
      const auto& cand = w.cands[w.accepted[j]];
      Finding& f = d.findings[j];
      f.evidence = cand.evidence;
      cand.describe(w.sol.theta[j], f);
    }
    d.noiseScale = w.sol.s;
    // The others, one per effect (its best variant), by score.
    std::vector<Finding> rest;
    std::set<std::string> taken;
    for (auto i : w.accepted) taken.insert(w.cands[i].effect);
    for (std::size_t i = 0; i < w.cands.size(); ++i) {
      if (taken.count(w.cands[i].effect)) continue;
      Finding f;
      f.effect = w.cands[i].effect;
      f.evidence = w.cands[i].evidence;
      f.score = lastScore[i];
      w.cands[i].describe(lastSol[i].theta.empty() ? 0.0 : lastSol[i].theta.back(), f);
      auto it = std::find_if(rest.begin(), rest.end(), [&](const Finding& g) { return g.effect == f.effect; });
      if (it == rest.end()) rest.push_back(f);
      else if (f.score > it->score) *it = f;
    }
    std::stable_sort(rest.begin(), rest.end(), [](const Finding& a, const Finding& b) { return a.score > b.score; });
    for (auto& f : rest) d.findings.push_back(f);
    run.d.axes.push_back(d);
    run.work.push_back(std::move(w));
  }
  return run;
}

AxisChange changeOf(const AxisDiagnosis& b, const AxisDiagnosis& a) {
  AxisChange ch;
  ch.channel = b.channel;
  ch.misfitBefore = b.misfit;
  ch.misfitAfter = a.misfit;
  ch.fractionOutsideBefore = b.fractionOutside;
  ch.fractionOutsideAfter = a.fractionOutside;
  return ch;
}

}  // namespace

Diagnosis diagnose(const Record& record, const ModelText& model, const DiagnoseOptions& options) {
  return diagnoseRun(record, model, options).d;
}

Improvement improve(const Record& record, const ModelText& model, const std::vector<AddRequest>& adds,
                    const DiagnoseOptions& options) {
  if (adds.empty()) throw InputError("nothing to add");
  Run run = diagnoseRun(record, model, options);
  Improvement imp;
  imp.before = run.d;
  std::array<std::vector<std::string>, 6> addYaml;
  std::array<double, 6> scale;
  scale.fill(1.0);
  std::array<std::vector<double>, 6> arReplace;
  std::vector<AxisChange> changes;
  for (auto& w : run.work) {
    // The requested effects of this channel, in the order of their diagnosis score.
    std::vector<std::string> wanted;
    for (const auto& a : adds) {
      if (!(a.channel.empty() || a.channel == w.d.channel)) continue;
      std::vector<std::string> effects{a.effect};
      if (a.effect == "found") {  // every reported finding of this channel
        effects.clear();
        for (const auto& f : w.d.findings)
          if (f.reported) effects.push_back(f.effect);
      }
      for (const auto& e : effects)
        if (std::find(wanted.begin(), wanted.end(), e) == wanted.end()) wanted.push_back(e);
    }
    AxisChange ch;
    ch.channel = w.d.channel;
    if (wanted.empty()) {
      changes.push_back(ch);
      continue;
    }
    std::stable_sort(wanted.begin(), wanted.end(), [&](const std::string& x, const std::string& y) {
      auto score = [&](const std::string& e) {
        for (const auto& f : w.d.findings)
          if (f.effect == e) return f.score;
        return -1.0;
      };
      return score(x) > score(y);
    });
    std::vector<const Candidate*> set;
    AllanSolution sol = solveAllan(w.prob, {}, {}, true);
    for (const auto& e : wanted) {
      const Candidate* bestC = nullptr;
      AllanSolution bestS;
      for (const auto& c : w.cands) {
        if (c.effect != e) continue;
        auto trial = set;
        trial.push_back(&c);
        auto start = sol.theta;
        start.push_back(-1.0);
        auto s = solveAllan(w.prob, trial, start, true);
        if (!bestC || s.chi2 < bestS.chi2) bestC = &c, bestS = s;
      }
      if (!bestC) {
        const auto present = modelEffectTypes(model.text, w.channel);
        std::string why = std::find(present.begin(), present.end(), e) != present.end()
                              ? "the model already has it"
                              : "no evidence in the record to size it (no temperature channel, no PSD "
                                "line or no isolated samples)";
        imp.notes.push_back("cannot add " + e + " to " + w.d.channel + ": " + why);
        continue;
      }
      set.push_back(bestC);
      sol = bestS;
    }
    // The base noise level is refitted only when the data ask for it: likelihood-ratio test of
    // s = 1 against s free, chi2 difference > 9 (3 sigma, one parameter). A base fitted to the
    // record usually has the right level, and the short-tau bands are too narrow for a level
    // nudged by the long-tau points.
    {
      const auto freeLevel = solveAllan(w.prob, set, sol.theta, false);
      if (sol.chi2 - freeLevel.chi2 > 9.0) sol = freeLevel;
    }
    // A base AR at the record's rate is refitted (Burg, same order) on the record with the added
    // effects taken out: the fitted deterministic signals subtracted, a random walk's level
    // removed by the steady-state RTS smoother of the local-level model (q = K^2 dt, r = the
    // record's variance; fit/composite_fit.hpp). The AR fitted to the raw record had absorbed
    // part of them (e.g. its low-frequency gain). Other bases keep their parameters; then the
    // level refit above applies.
    const auto arBase = arOfChannel(model.text, w.channel, record.rate_hz);
    bool arRefitted = false;
    if (arBase) {
      std::vector<double> x = channelData(record, w.channel);
      bool any = false;
      for (std::size_t j = 0; j < set.size(); ++j) {
        if (!set[j]->signal.empty()) {
          for (std::size_t k = 0; k < x.size(); ++k) x[k] -= set[j]->signal[k];
          any = true;
        } else if (set[j]->effect == "random_walk" && sol.theta[j] > 0) {
          double m = 0, v = 0;
          for (double xv : x) m += xv;
          m /= double(x.size());
          for (double xv : x) v += (xv - m) * (xv - m);
          v /= double(x.size());
          const auto level = fit::localLevelSmoother(x, sol.theta[j] / record.rate_hz, v);
          for (std::size_t k = 0; k < x.size(); ++k) x[k] -= level[k];
          any = true;
        }
      }
      // A lattice quantization (no signal to subtract): Yule-Walker on the autocovariance with
      // the rounding noise's taken out; the variant (carried or not) that fits the Allan curve
      // better with its refitted AR is kept.
      const Candidate* lat = nullptr;
      for (auto* c : set)
        if (c->lsbRate > 0) lat = c;
      if (lat) {
        std::vector<double> bestA;
        double bestE = 0, bestChi = INFINITY;
        const Candidate* bestC = nullptr;
        for (const auto& c : w.cands) {
          if (!(c.lsbRate > 0)) continue;
          std::vector<double> a;
          double E = 0;
          if (!arWithoutQuantization(x, arBase->size() - 1, c.lsbRate, c.carry, a, E)) continue;
          const auto av = fit::arAllanVariance(a, E, setupFactors(w));
          AllanProblem p2 = w.prob;
          for (std::size_t k = 0; k < av.size(); ++k) p2.mu[k] = av[k];
          std::vector<const Candidate*> s2;
          for (auto* c2 : set) s2.push_back(c2 == lat ? &c : c2);
          const auto sol2 = solveAllan(p2, s2, sol.theta, true);
          if (sol2.chi2 < bestChi) bestChi = sol2.chi2, bestA = a, bestE = E, bestC = &c;
        }
        if (bestC) {
          std::replace(set.begin(), set.end(), lat, bestC);
          arReplace[std::size_t(w.channel)].assign(bestA.begin() + 1, bestA.end());
          arReplace[std::size_t(w.channel)].push_back(std::sqrt(bestE));
          arRefitted = true;
          sol.s = 1.0;
          any = false;  // the signals (if any) are refitted below only without a lattice
        }
      }
      // Stochastic terms with a known autocovariance (bias instability): Yule-Walker on the
      // record's autocovariance minus theirs.
      std::vector<double> rSub;
      const std::size_t order = arBase->size() - 1;
      for (std::size_t j = 0; j < set.size(); ++j)
        if (set[j]->acov && sol.theta[j] > 0) {
          const auto r = set[j]->acov(order);
          rSub.resize(order + 1, 0.0);
          for (std::size_t k = 0; k <= order; ++k) rSub[k] += sol.theta[j] * r[k];
        }
      if (!rSub.empty() && !arRefitted) {
        double m = 0;
        for (double v : x) m += v;
        m /= double(x.size());
        std::vector<double> xc(x.size());
        for (std::size_t k = 0; k < x.size(); ++k) xc[k] = x[k] - m;
        auto r = fit::biasedAutocovariance(xc, order);
        for (std::size_t k = 0; k <= order; ++k) r[k] -= rSub[k];
        try {
          const auto f = fit::yuleWalkerFromAutocovariance(r, order, x.size());
          if (f.drivingVariance > 0 && fit::arMaxPoleMagnitude(f.a) < 1) {
            arReplace[std::size_t(w.channel)].assign(f.a.begin() + 1, f.a.end());
            arReplace[std::size_t(w.channel)].push_back(std::sqrt(f.drivingVariance));
            arRefitted = true;
            sol.s = 1.0;
            any = false;
          }
        } catch (const Error&) {
        }
      }
      if (any) {
        const auto refit = fit::burg(x, arBase->size() - 1);
        arReplace[std::size_t(w.channel)].assign(refit.a.begin() + 1, refit.a.end());
        arReplace[std::size_t(w.channel)].push_back(std::sqrt(refit.drivingVariance));
        arRefitted = true;
        sol.s = 1.0;
      }
    }
    for (std::size_t j = 0; j < set.size(); ++j) {
      if (set[j]->freeSize && !(sol.theta[j] > 0)) {
        imp.notes.push_back(set[j]->effect + " on " + w.d.channel +
                            ": fitted size 0 (the data do not want it), not added");
        continue;
      }
      Finding f;
      set[j]->describe(sol.theta[j], f);
      addYaml[std::size_t(w.channel)].push_back(f.yaml);
      ch.added.push_back(f.yaml);
    }
    if (!ch.added.empty() && !arRefitted) {
      scale[std::size_t(w.channel)] = sol.s;
      ch.noiseScale = sol.s;
    }
    if (arRefitted) imp.notes.push_back(w.d.channel + ": base AR refitted (Burg, order " +
                                        std::to_string(arBase->size() - 1) +
                                        ") on the record with the added effects taken out");
    changes.push_back(ch);
  }
  std::string header = "Improved by sinsim diagnose from " + model.name + " and " + record.source + ":";
  for (const auto& ch : changes)
    for (const auto& a : ch.added) header += "\n  " + ch.channel + " += " + a;
  for (const auto& ch : changes)
    if (!ch.added.empty() && std::fabs(ch.noiseScale - 1) > 1e-9)
      header += "\n  " + ch.channel + ": base noise scaled by sqrt(" + num(ch.noiseScale, 6) + ")";
  imp.model.name = model.name + " (improved)";
  imp.model.text = editModel(model.text, addYaml, scale, header, arReplace);
  imp.after = diagnose(record, imp.model, options);
  for (auto& ch : changes) {
    const auto& b = imp.before.axis(ch.channel);
    const auto& a = imp.after.axis(ch.channel);
    AxisChange full = changeOf(b, a);
    full.added = ch.added;
    full.noiseScale = ch.noiseScale;
    imp.changes.push_back(full);
  }
  return imp;
}

Improvement compareModels(const Record& record, const ModelText& before, const ModelText& after,
                          const DiagnoseOptions& options) {
  Improvement imp;
  imp.before = diagnose(record, before, options);
  imp.after = diagnose(record, after, options);
  imp.model = after;
  for (const auto& b : imp.before.axes) imp.changes.push_back(changeOf(b, imp.after.axis(b.channel)));
  return imp;
}

// ---- model editing -------------------------------------------------------------------------------

namespace {

/// The keys holding a stochastic effect's noise level (scaled by sqrt of the variance factor).
std::vector<std::string> noiseKeys(const std::string& type) {
  if (type == "ar") return {"sigma", "output_sigma"};
  if (type == "white") return {"density", "sigma"};
  if (type == "gauss_markov") return {"sigma"};
  if (type == "random_walk") return {"K"};
  if (type == "bias_instability") return {"B", "floor"};
  return {};
}

bool scalable(const YAML::Node& e) {
  return e.IsMap() && e["type"] && !noiseKeys(e["type"].as<std::string>()).empty();
}

void scaleEffect(YAML::Node e, double factor) {
  for (const auto& key : noiseKeys(e["type"].as<std::string>())) {
    if (!e[key] || !e[key].IsScalar()) continue;
    const std::string text = e[key].as<std::string>();
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end == text.c_str()) continue;
    e[key] = num(v * factor, 9) + std::string(end);
  }
}

void flowStyle(YAML::Node n) {
  if (n.IsSequence())
    for (auto e : n)
      if (e.IsMap()) e.SetStyle(YAML::EmitterStyle::Flow);
}

}  // namespace

namespace detail {

std::string editModel(const std::string& modelText,
                      const std::array<std::vector<std::string>, 6>& addYaml,
                      const std::array<double, 6>& varianceScale, const std::string& header,
                      const std::array<std::vector<double>, 6>& arReplace) {
  YAML::Node root = YAML::Load(modelText);
  if (!root.IsMap()) root = YAML::Node(YAML::NodeType::Map);
  for (int sensor = 0; sensor < 2; ++sensor) {
    const char* sname = sensor == 0 ? "gyro" : "accel";
    bool any = false, differs = false;
    for (int a = 0; a < 3; ++a) {
      const int c = sensor * 3 + a;
      any = any || !addYaml[std::size_t(c)].empty() || varianceScale[std::size_t(c)] != 1.0 ||
            !arReplace[std::size_t(c)].empty();
      differs = differs || varianceScale[std::size_t(c)] != 1.0 || !arReplace[std::size_t(c)].empty();
    }
    if (!any) continue;
    YAML::Node s = root[sname];
    if (!s || !s.IsMap()) {
      root[sname] = YAML::Node(YAML::NodeType::Map);
      s = root[sname];
    }
    // Scalable effects of `all` move to the axis lists when the axes are scaled differently.
    std::vector<YAML::Node> moved;
    if (differs && s["all"] && s["all"].IsSequence()) {
      YAML::Node keep(YAML::NodeType::Sequence);
      for (const auto& e : s["all"]) {
        if (scalable(e)) moved.push_back(YAML::Clone(e));
        else keep.push_back(e);
      }
      if (keep.size() == 0) s.remove("all");
      else s["all"] = keep;
    }
    for (int a = 0; a < 3; ++a) {
      const int c = sensor * 3 + a;
      const double f = std::sqrt(varianceScale[std::size_t(c)]);
      YAML::Node list(YAML::NodeType::Sequence);
      const auto& rep = arReplace[std::size_t(c)];
      auto edit = [&](const YAML::Node& e) {
        YAML::Node copy = YAML::Clone(e);
        const bool isAr = copy.IsMap() && copy["type"] && copy["type"].as<std::string>() == "ar";
        if (isAr && !rep.empty()) {
          YAML::Node a(YAML::NodeType::Sequence);
          for (std::size_t i = 0; i + 1 < rep.size(); ++i) a.push_back(num(rep[i], 10));
          a.SetStyle(YAML::EmitterStyle::Flow);
          copy["a"] = a;
          copy.remove("output_sigma");
          copy["sigma"] = quantity(rep.back(), unitsFor(c).level);
        } else if (scalable(copy) && f != 1.0) {
          scaleEffect(copy, f);
        }
        return copy;
      };
      for (const auto& e : moved) list.push_back(edit(e));
      const char* an = axisName(c);
      if (s[an] && s[an].IsSequence())
        for (const auto& e : s[an]) list.push_back(edit(e));
      for (const auto& y : addYaml[std::size_t(c)]) list.push_back(YAML::Load(y));
      if (list.size() > 0 || (s[an] && s[an].IsDefined())) s[an] = list;
    }
  }
  for (auto kv : root)
    if (kv.second.IsMap())
      for (auto l : kv.second) flowStyle(l.second);
  YAML::Emitter out;
  out << root;
  std::string text;
  std::istringstream hs(header);
  std::string line;
  while (std::getline(hs, line)) text += "# " + line + "\n";
  return text + out.c_str() + "\n";
}

}  // namespace detail

// ---- JSON and the table ------------------------------------------------------------------------

namespace {

nlohmann::json curveJson(const Comparison& c, const char* xname) {
  nlohmann::json j;
  j[xname] = c.x;
  j["meas"] = c.meas;
  j["model"] = c.model;
  j["lo"] = c.lo;
  j["hi"] = c.hi;
  j["outside"] = c.outside;
  return j;
}

nlohmann::json axisJson(const AxisDiagnosis& a, double threshold) {
  nlohmann::json j;
  j["channel"] = a.channel;
  j["misfit"] = a.misfit;
  j["misfit_raw"] = a.misfitRaw;
  j["misfit_floor"] = a.misfitFloor;
  j["fraction_outside"] = a.fractionOutside;
  j["chi2"] = a.chi2;
  j["chi2_points"] = a.chi2Points;
  j["noise_scale"] = a.noiseScale;
  j["fits"] = a.fits(threshold);
  if (a.ljungBox)
    j["ljung_box"] = {{"lags", a.ljungBox->lags}, {"dof", a.ljungBox->dof}, {"Q", a.ljungBox->Q},
                      {"p", a.ljungBox->pValue}};
  else
    j["ljung_box"] = nullptr;
  j["fails"] = nlohmann::json::array();
  for (const auto& f : a.fails)
    j["fails"].push_back({{"statistic", f.statistic}, {"from", f.from}, {"to", f.to},
                          {"unit", f.statistic == "adev" ? "s" : "Hz"},
                          {"direction", f.direction > 0 ? "above" : "below"},
                          {"worst_ratio", f.worstRatio}, {"points", f.points}});
  j["findings"] = nlohmann::json::array();
  for (const auto& f : a.findings)
    j["findings"].push_back({{"effect", f.effect}, {"evidence", f.evidence}, {"size", f.size},
                             {"yaml", f.yaml}, {"params", f.params}, {"score", f.score},
                             {"reported", f.reported}});
  j["units"] = {{"adev", "SI (rad/s or m/s^2)"}, {"psd", "SI^2/Hz"}, {"tau", "s"}, {"f", "Hz"}};
  j["curves"] = {{"adev", curveJson(a.adev, "tau")}, {"psd", curveJson(a.psd, "f")},
                 {"acf", curveJson(a.acf, "lag")}};
  return j;
}

nlohmann::json diagnosisJson(const Diagnosis& d) {
  nlohmann::json j;
  j["data"] = d.data;
  j["model"] = d.model;
  j["rate_hz"] = d.rate;
  j["samples"] = d.samples;
  j["realisations"] = d.realisations;
  j["threshold"] = d.threshold;
  j["band_level"] = d.bandLevel;
  j["axes"] = nlohmann::json::array();
  for (const auto& a : d.axes) j["axes"].push_back(axisJson(a, d.threshold));
  return j;
}

std::string pad(std::string s, std::size_t w) {
  // display width: count UTF-8 lead bytes
  std::size_t n = 0;
  for (unsigned char ch : s) n += (ch & 0xC0) != 0x80;
  if (n < w) s.append(w - n, ' ');
  return s;
}

std::string findingsText(const AxisDiagnosis& a, double threshold) {
  std::string s;
  for (const auto& f : a.findings)
    if (f.reported) s += (s.empty() ? "" : ", ") + f.effect + " (" + num(f.score, 3) + ")";
  if (s.empty()) s = a.fits(threshold) ? "fits" : "no effect above threshold";
  return s;
}

}  // namespace

std::string toJson(const Diagnosis& d) { return diagnosisJson(d).dump(1) + "\n"; }

std::string toJson(const Improvement& imp) {
  nlohmann::json j;
  j["model_written"] = imp.model.name;
  j["notes"] = imp.notes;
  j["axes"] = nlohmann::json::array();
  for (const auto& ch : imp.changes) {
    nlohmann::json a = axisJson(imp.before.axis(ch.channel), imp.before.threshold);
    a["misfit_before"] = ch.misfitBefore;
    a["misfit_after"] = ch.misfitAfter;
    a["fraction_outside_before"] = ch.fractionOutsideBefore;
    a["fraction_outside_after"] = ch.fractionOutsideAfter;
    a["added"] = ch.added;
    a["noise_scale_applied"] = ch.noiseScale;
    a["after"] = axisJson(imp.after.axis(ch.channel), imp.after.threshold);
    j["axes"].push_back(a);
  }
  j["before"] = {{"model", imp.before.model}, {"data", imp.before.data},
                 {"realisations", imp.before.realisations}};
  return j.dump(1) + "\n";
}

std::string summaryTable(const Diagnosis& d) {
  std::ostringstream o;
  o << "diagnosis of " << d.data << " (" << d.samples << " samples at " << num(d.rate, 6)
    << " Hz) against " << d.model << ", " << d.realisations << " realisations, "
    << num(100 * d.bandLevel, 3) << " % bands, reporting threshold " << num(d.threshold, 3) << "\n";
  o << pad("channel", 8) << pad("misfit", 8) << pad("outside", 9) << pad("chi2/K", 13)
    << pad("Ljung-Box p", 13) << "findings (score)\n";
  for (const auto& a : d.axes) {
    o << pad(a.channel, 8) << pad(num(a.misfit, 3), 8)
      << pad(num(100 * a.fractionOutside, 3) + " %", 9)
      << pad(num(a.chi2, 4) + "/" + std::to_string(a.chi2Points), 13)
      << pad(a.ljungBox ? num(a.ljungBox->pValue, 2) : "-", 13) << findingsText(a, d.threshold) << "\n";
  }
  for (const auto& a : d.axes) {
    bool head = false;
    for (const auto& f : a.fails) {
      if (!head) o << a.channel << " fails:";
      head = true;
      o << " " << f.statistic << " " << num(f.from, 3) << ".." << num(f.to, 3)
        << (f.statistic == "adev" ? " s " : " Hz ") << (f.direction > 0 ? "above" : "below")
        << " (x" << num(f.worstRatio, 3) << ");";
    }
    if (head) o << "\n";
    for (const auto& f : a.findings)
      if (f.reported) o << "  " << a.channel << " " << f.effect << ": " << f.size << " — " << f.evidence << "\n";
  }
  return o.str();
}

std::string summaryTable(const Improvement& imp) {
  std::ostringstream o;
  o << summaryTable(imp.before) << "\n";
  o << pad("channel", 8) << pad("misfit before", 15) << pad("after", 8) << pad("outside before", 16)
    << pad("after", 8) << "added\n";
  for (const auto& ch : imp.changes) {
    std::string added;
    for (const auto& a : ch.added) added += (added.empty() ? "" : "; ") + a;
    o << pad(ch.channel, 8) << pad(num(ch.misfitBefore, 3), 15) << pad(num(ch.misfitAfter, 3), 8)
      << pad(num(100 * ch.fractionOutsideBefore, 3) + " %", 16)
      << pad(num(100 * ch.fractionOutsideAfter, 3) + " %", 8) << (added.empty() ? "-" : added) << "\n";
  }
  for (const auto& n : imp.notes) o << "note: " << n << "\n";
  return o.str();
}

}  // namespace sinsim::errormodels::diagnose
