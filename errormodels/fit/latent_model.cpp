#include "errormodels/fit/latent_model.hpp"

#include <array>
#include <cmath>
#include <complex>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "errormodels/fit/allan_fit.hpp"
#include "errormodels/fit/ar_fit.hpp"
#include "errormodels/gm_process.hpp"

namespace sinsim::errormodels::fit {

namespace {

/// The five Allan-term coefficients; a lattice quantization is left to its own form (latticeScale).
std::array<double, kAllanTermCount> allanTheta(const LatentModel& mdl) {
  const auto sq = [](double v) { return v * v; };
  const double q = mdl.lattice.active() ? 0.0 : sq(mdl.quantization);
  return {q, sq(mdl.white), sq(mdl.flicker), sq(mdl.randomWalk), sq(mdl.drift)};
}

/// 12 Q^2 / D^2: the lattice rounding's forms (at Q = D / sqrt 12) scaled to the model's Q; 0
/// without a lattice or a quantization.
double latticeScale(const LatentModel& mdl) {
  if (!mdl.lattice.active() || !(mdl.quantization > 0.0)) return 0.0;
  const double r = mdl.quantization / mdl.lattice.step;
  return 12.0 * r * r;
}

}  // namespace

std::string LatentModel::termNames() const {
  std::string s;
  auto add = [&](bool on, const char* name) {
    if (!on) return;
    if (!s.empty()) s += " + ";
    s += name;
  };
  add(quantization > 0.0, "quantization");
  add(white > 0.0, "white");
  add(arVariance > 0.0, "ar");
  for (std::size_t i = 0; i < gm.size(); ++i) add(true, "gm");
  add(flicker > 0.0, "flicker");
  add(randomWalk > 0.0, "random_walk");
  add(drift > 0.0, "drift");
  return s.empty() ? "none" : s;
}

double gmDiscreteAllanVariance(double s2, double T, double dt, std::size_t m) {
  if (m == 0 || !(T > 0.0) || !(dt > 0.0))
    throw InputError("GM Allan variance: need m >= 1, tau > 0 and dt > 0");
  const double phi = std::exp(-dt / T);
  const double omp = -std::expm1(-dt / T);  // 1 - phi without cancellation
  const double md = static_cast<double>(m);
  const double phim = std::pow(phi, md);
  const double omPhim = -std::expm1(-md * dt / T);  // 1 - phi^m
  // The bracket m (1 - phi^2) - phi (1 - phi^m)(3 - phi^m) is ~(2/3) m^3 u^3 (u = 1 - phi) while
  // its terms are ~2 m u: for m u < 1e-4 (digits lost > 8) use its expansion in u, exact to
  // O((m u)^2) relative (sympy; checked against the closed form in tests/fit/test_latent_model.cpp):
  //   bracket = m (2 m^2 + 1)/3 u^3 - m (m - 1)(3 m^2 + m + 1)/6 u^4 + O(u^5).
  if (md * omp < 1e-4) {
    const double u = omp;
    return s2 * u * (2.0 * md * md + 1.0) / (3.0 * md) *
           (1.0 - (md - 1.0) * (3.0 * md * md + md + 1.0) * u / (2.0 * (2.0 * md * md + 1.0)));
  }
  const double bracket = md * omp * (1.0 + phi) - phi * omPhim * (3.0 - phim);
  return s2 * bracket / (md * md * omp * omp);
}

double gmAveragedAllanVariance(double s2, double T, double dt, std::size_t m) {
  if (m == 0 || !(T > 0.0) || !(dt > 0.0))
    throw InputError("GM Allan variance: need m >= 1, tau > 0 and dt > 0");
  return gaussMarkovAllanVariance(s2, T, static_cast<double>(m) * dt);  // the continuous form's home
}

double gmAllanVariance(const GmTerm& g, double dt, std::size_t m) {
  const double s2 = g.sigma * g.sigma;
  return g.averaged ? gmAveragedAllanVariance(s2, g.tau, dt, m) : gmDiscreteAllanVariance(s2, g.tau, dt, m);
}

double flickerSampledAllanVariance(double B2, std::size_t m) {
  if (m == 0) throw InputError("flicker Allan variance: need m >= 1");
  if (m > 4096) {  // the averaged flicker's floor, fit::allanModelAdev's (its one home; any tau)
    const double floor = allanModelAdev({0.0, 0.0, B2, 0.0, 0.0}, {1.0}).front();
    return floor * floor;
  }
  static const double x8[] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                              0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
  static const double w8[] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                              0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  const double md = static_cast<double>(m);
  const std::size_t panels = 4 * m;  // width 1/(8m): a quarter of the numerator's period 1/m
  const double h = 0.5 / static_cast<double>(panels);
  double sum = 0.0;
  for (std::size_t k = 0; k < panels; ++k)
    for (int i = 0; i < 8; ++i) {
      const double x = (static_cast<double>(k) + 0.5 + 0.5 * x8[i]) * h;
      const double a = std::sin(kPi * md * x), b = std::sin(kPi * x);
      sum += w8[i] * 0.5 * h * 2.0 * a * a * a * a / (md * md * x * b * b);
    }
  return B2 / kPi * sum;
}

namespace {

/// The AR term's Allan variance per unit driving variance at the factors m (linear in E). A fit
/// evaluates it for one fixed polynomial many times, each an autocovariance recursion to 2 max(m)
/// lags, so the last one is kept per thread.
const std::vector<double>& arUnitAllanVariance(const std::vector<double>& a, const std::vector<std::size_t>& m) {
  thread_local std::vector<double> lastA, unit;
  thread_local std::vector<std::size_t> lastM;
  if (unit.empty() || a != lastA || m != lastM) {
    unit = arAllanVariance(a, 1.0, m);
    lastA = a;
    lastM = m;
  }
  return unit;
}

}  // namespace

std::vector<double> latentAllanVariance(const LatentModel& model, double dt,
                                        const std::vector<std::size_t>& m) {
  if (!(std::isfinite(dt) && dt > 0.0)) throw InputError("latent model: dt must be > 0");
  std::vector<double> tau(m.size());
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (m[i] == 0) throw InputError("latent model: averaging factor m must be >= 1");
    tau[i] = static_cast<double>(m[i]) * dt;
  }
  std::vector<double> avar = allanModelAdev(allanTheta(model), tau);
  for (std::size_t i = 0; i < m.size(); ++i) {
    avar[i] *= avar[i];
    for (const GmTerm& g : model.gm) avar[i] += gmAllanVariance(g, dt, m[i]);
  }
  if (const double q = latticeScale(model); q > 0.0)
    for (std::size_t i = 0; i < m.size(); ++i) avar[i] += q * latticeQuantizationAllanVariance(model.lattice, dt, m[i]);
  if (model.arVariance > 0.0) {
    const std::vector<double>& ar = arUnitAllanVariance(model.arPolynomial, m);
    for (std::size_t i = 0; i < m.size(); ++i) avar[i] += model.arVariance * ar[i];
  }
  return avar;
}

double latentPsd(const LatentModel& model, double dt, double w) { return LatentSpectrum(model, dt)(w); }

// A GM term's PSD at w in its convention: the AR(1)'s sigma^2 (1 - phi^2) / |1 - phi e^{-iw}|^2,
// or for the averaged samples (autocovariance c0, then c1 phi^(k-1))
// c0 + 2 c1 (cos w - phi) / |1 - phi e^{-iw}|^2; with s = sin(w/2), cos w = 1 - 2 s^2, so
// |1 - phi e^{-iw}|^2 = (1 - phi)^2 + 4 phi s^2 and cos w - phi = (1 - phi) - 2 s^2.
LatentSpectrum::LatentSpectrum(const LatentModel& model, double dt)
    : dt_(dt), theta_(allanTheta(model)), latticeScale_(latticeScale(model)), lattice_(model.lattice),
      arPolynomial_(model.arPolynomial), arVariance_(model.arVariance) {
  theta_[4] = 0.0;  // the ramp is deterministic
  anyAllanTerm_ = theta_[0] != 0.0 || theta_[1] != 0.0 || theta_[2] != 0.0 || theta_[3] != 0.0;
  for (const GmTerm& g : model.gm) {
    Gm t{};
    const double s2 = g.sigma * g.sigma, u = dt / g.tau;
    const double phi = std::exp(-u);
    t.averaged = g.averaged;
    t.omPhi = -std::expm1(-u), t.omPhi2 = t.omPhi * t.omPhi, t.fourPhi = 4.0 * phi;
    t.num = s2 * t.omPhi * (1.0 + phi);
    if (g.averaged) {  // c0, c1: the averaged samples' autocovariance (its one home)
      std::vector<double> c(2, 0.0);
      addGaussMarkovIntervalAcov(s2, g.tau, dt, c);
      t.c0 = c[0], t.twoC1 = 2.0 * c[1];
    }
    gm_.push_back(t);
  }
}

double LatentSpectrum::operator()(double w) const { return (*this)(w, std::sin(0.5 * w)); }

double LatentSpectrum::operator()(double w, double s) const {
  const double s2 = s * s;
  double S = anyAllanTerm_ ? allanTermsPsd(theta_, dt_, w, s) : 0.0;
  if (latticeScale_ > 0.0) S += latticeScale_ * latticeQuantizationPsd(lattice_, dt_, w);
  for (const Gm& g : gm_) {
    const double den = g.omPhi2 + g.fourPhi * s2;
    S += g.averaged ? g.c0 + g.twoC1 * (g.omPhi - 2.0 * s2) / den : g.num / den;
  }
  if (arVariance_ > 0.0) {
    // E / |A(e^{iw})|^2, A(z) = sum_k a_k z^-k: Horner in u = e^{-iw} (one sincos per call)
    const std::complex<double> u = std::polar(1.0, -w);
    std::complex<double> A = 0.0;
    for (std::size_t k = arPolynomial_.size(); k-- > 0;) A = A * u + arPolynomial_[k];
    S += arVariance_ / std::norm(A);
  }
  return S;
}

double latentInnovationVariance(const LatentModel& model, double dt) {
  constexpr int kNodes = 1 << 15;
  const double h = kPi / kNodes;
  const LatentSpectrum psd(model, dt);
  double sumLog = 0.0;
  for (int i = 0; i < kNodes; ++i) {
    const double S = psd((i + 0.5) * h);
    if (!(S > 0.0) || !std::isfinite(S))
      throw InputError("latentInnovationVariance: the model " + model.termNames() + " has no random term");
    sumLog += std::log(S);
  }
  return std::exp(sumLog / kNodes);
}

}  // namespace sinsim::errormodels::fit
