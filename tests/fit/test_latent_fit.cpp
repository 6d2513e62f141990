// The composite latent-process fit (errormodels/fit/latent_fit.hpp): exact recovery from the
// closed-form Allan variance, sanity warnings, and a small seeded slice of the round-trip study
// (bench/latent_fit_study.cpp; the full study and its rates are in docs/fitting.md).
#include <catch2/catch.hpp>
#include <fftw3.h>

#include <random>

#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "../identify/identify_test_util.hpp"
#include "common/constants.hpp"
#include "common/error.hpp"
#include "errormodels/fit/latent_fit.hpp"

using namespace sinsim::errormodels::fit;

namespace {

std::vector<std::size_t> octaves(std::size_t N) {
  std::vector<std::size_t> m;
  for (std::size_t k = 1; 10 * k <= N; k *= 2) m.push_back(k);
  return m;
}

}  // namespace

TEST_CASE("latent fit recovers every term set from its exact Allan variance", "[fit][latent]") {
  const double dt = 0.01;
  const std::size_t N = 720000;  // 2 h at 100 Hz
  const auto m = octaves(N);
  struct Truth { LatentTermSet set; LatentModel model; };
  std::vector<Truth> truths;
  {
    LatentModel a; a.white = 5.8e-5; a.gm = {{8.7e-5, 3.0}};
    truths.push_back({{false, true, 1, false, false, false}, a});
    LatentModel b = a; b.randomWalk = 2e-6;
    truths.push_back({{false, true, 1, false, true, false}, b});
    LatentModel c = a; c.gm.push_back({5.2e-5, 30.0});
    truths.push_back({{false, true, 2, false, false, false}, c});
    LatentModel d; d.white = 5.8e-5; d.flicker = 2.7e-5; d.randomWalk = 3e-6;
    truths.push_back({{false, true, 0, true, true, false}, d});
    LatentModel e; e.white = 5.8e-5; e.quantization = 1.7e-6;
    truths.push_back({{true, true, 0, false, false, false}, e});
  }
  for (const auto& t : truths) {
    INFO(t.set.name());
    const auto avar = latentAllanVariance(t.model, dt, m);
    LatentFitOptions o;
    o.sampleInterval = dt;
    const LatentFit f = fitLatentModel(m, avar, N, o);
    CHECK(f.terms == t.set);
    if (!(f.terms == t.set)) continue;
    // Exact data: the only error is the golden-section tolerance on tau (0.618^28 of a factor
    // sqrt 2 in log T ~ 5e-7) and NNLS round-off.
    CHECK(f.model.white == Approx(t.model.white).epsilon(1e-4));
    CHECK(f.model.quantization == Approx(t.model.quantization).epsilon(1e-4));
    CHECK(f.model.randomWalk == Approx(t.model.randomWalk).epsilon(1e-4).margin(1e-12));
    CHECK(f.model.flicker == Approx(t.model.flicker).epsilon(1e-4).margin(1e-12));
    REQUIRE(f.model.gm.size() == t.model.gm.size());
    for (std::size_t g = 0; g < f.model.gm.size(); ++g) {
      CHECK(f.model.gm[g].sigma == Approx(t.model.gm[g].sigma).epsilon(1e-4));
      CHECK(f.model.gm[g].tau == Approx(t.model.gm[g].tau).epsilon(1e-4));
    }
    CHECK(f.chi2 < 1e-6);
    CHECK(f.runnerUp() != nullptr);
    // Every parameter states an interval in ln; an amplitude's is the delta method's of ln theta
    // (theta = amplitude^2, the covariance's own space), halved: sd(ln amplitude) = its statistical
    // stdError / value, with each discretisation shift d added in quadrature as ln(1 + d / value)
    // (to stdError as d).
    for (const auto& p : f.parameters) {
      INFO(p.name);
      REQUIRE(p.logScale);
      CHECK(p.logCenter == Approx(std::log(p.value)).epsilon(1e-12));
      if (p.name.find(".tau") == std::string::npos) {
        const double dg = p.gmConventionShift, df = p.flickerConventionShift;
        const double statistical = std::sqrt(std::max(0.0, p.stdError * p.stdError - dg * dg - df * df)) / p.value;
        const double lg = std::log1p(dg / p.value), lf = std::log1p(df / p.value);
        CHECK(p.logLower == Approx(std::sqrt(statistical * statistical + lg * lg + lf * lf)).epsilon(1e-9));
        CHECK(p.logUpper == p.logLower);
      }
    }
  }
}

TEST_CASE("latent fit warns about a GM tau below two samples",
          "[fit][latent]") {
  const double dt = 0.01;
  const std::size_t N = 120000;
  const auto m = octaves(N);
  LatentFitOptions o;
  o.sampleInterval = dt;
  o.candidates = {{false, true, 1, false, false, false}};
  // (A tau above a third of the record cannot be fitted: T is searched up to the largest tau
  // used, N dt / 10.)
  for (double T : {1.5 * dt}) {
    LatentModel t; t.white = 5.8e-5; t.gm = {{2e-4, T}};
    const LatentFit f = fitLatentModel(m, latentAllanVariance(t, dt, m), N, o);
    bool warned = false;
    for (const auto& w : f.warnings) warned = warned || w.find("gm1.tau") != std::string::npos;
    CHECK(warned);
  }
  LatentModel ok; ok.white = 5.8e-5; ok.gm = {{2e-4, 2.0}};
  const LatentFit f = fitLatentModel(m, latentAllanVariance(ok, dt, m), N, o);
  CHECK(f.warnings.empty());
}

TEST_CASE("latent fit's selection-aware parameters on exact data: weights bounded by the penalties",
          "[fit][latent]") {
  // Exact Allan variance of white + GM at 100 Hz, 2 h. Every valid set near the top fits the
  // curve exactly (the truth with chi^2 ~ 0, a superset with its extra variance ~ 0), so the
  // averaged values are the truth (1e-4: the golden-section tolerance on tau, as above) and every
  // set has a GM (the sets without one miss by chi^2 >> 40: inclusion 1). A superset's weight
  // relative to the truth is exp(-(chi^2 gain + penalty) / 2) <= exp(-penalty / 2), chi^2 gain ~ 0
  // here: a one-parameter extra term is included with weight <= exp(-5.41 / 2) = 0.0669, a
  // second GM with <= exp(-7.82 / 2) = 0.0200 (latentPenalty).
  const double dt = 0.01;
  const std::size_t N = 720000;
  const auto m = octaves(N);
  LatentModel t; t.white = 5.8e-5; t.gm = {{8.7e-5, 3.0}};
  LatentFitOptions o;
  o.sampleInterval = dt;
  const LatentFit f = fitLatentModel(m, latentAllanVariance(t, dt, m), N, o);
  REQUIRE(f.terms == LatentTermSet{false, true, 1, false, false, false});
  const std::map<std::string, double> truth{{"white", t.white}, {"gm1.sigma", t.gm[0].sigma}, {"gm1.tau", t.gm[0].tau}};
  std::size_t seen = 0;
  for (const auto& a : f.averaged) {
    INFO(a.name << " " << a.value << " +- " << a.stdError << ", weight " << a.inclusion);
    CHECK(std::isfinite(a.stdError));
    if (const auto it = truth.find(a.name); it != truth.end()) {
      ++seen;
      CHECK(a.inclusion == Approx(1.0).margin(1e-12));
      CHECK(a.value == Approx(it->second).epsilon(1e-4));
    } else if (a.name.rfind("gm2.", 0) == 0) {
      CHECK(a.inclusion <= std::exp(-7.82 / 2.0) * (1.0 + 1e-6));
    } else {
      CHECK(a.inclusion <= std::exp(-5.41 / 2.0) * (1.0 + 1e-6));
    }
  }
  CHECK(seen == truth.size());
}

TEST_CASE("latent fit refuses bad input", "[fit][latent]") {
  LatentFitOptions o;
  CHECK_THROWS_AS(fitLatentModel(std::vector<double>(1000, 1.0), o), sinsim::InputError);  // no dt
  o.sampleInterval = 0.01;
  CHECK_THROWS_AS(fitLatentModel(std::vector<double>(10, 1.0), o), sinsim::InputError);
  std::vector<double> x(1000, 0.0);
  x[3] = NAN;
  CHECK_THROWS_AS(fitLatentModel(x, o), sinsim::InputError);
}

TEST_CASE("latent fit round trip, seeded slice of the study: set and 2-sigma coverage", "[fit][latent]") {
  // White + GM and white + GM + RW at 100 Hz, 20 min (the study's parameters), 8 seeds each.
  // Bound: at least 13 of 16 right sets and 90 % of the parameter checks (docs/fitting.md has
  // the study: 20/20 right for white + GM, 2-sigma coverage 90-100 %). A true rate of 0.6 would
  // pass 13/16 with probability < 2 % (binomial), so the slice catches a broken selection or
  // uncertainty, not a 5 % drift.
  const double rate = 100.0, duration = 1200.0;
  const double N = 0.2 * sinsim::kRadPerDeg / 60.0, s1 = 0.005 * sinsim::kRadPerDeg, T1 = duration / 2400.0;
  const double K = 200.0 * N / duration;
  char body[512];
  std::snprintf(body, sizeof body,
                "gyro:\n  x:\n    - {type: white, density: %.10g rad/sqrt(s)}\n"
                "    - {type: gauss_markov, sigma: %.10g rad/s, tau: %.10g s, rate: 100 Hz}\n",
                N, s1, T1);
  const std::string rw = "    - {type: random_walk, K: " + std::to_string(K) + " rad/s/sqrt(s)}\n";
  int right = 0, total = 0, covered = 0, checks = 0;
  for (int withRw = 0; withRw < 2; ++withRw)
    for (int s = 0; s < 8; ++s) {
      const auto r = identify_test::staticRecord(std::string(body) + (withRw ? rw : ""), rate, duration,
                                                 7000 + std::uint64_t(s));
      LatentFitOptions o;
      o.sampleInterval = 1.0 / rate;
      const LatentFit f = fitLatentModel(r.gyro[0], o);
      ++total;
      const LatentTermSet want{false, true, 1, false, withRw == 1, false};
      if (!(f.terms == want)) continue;
      ++right;
      std::vector<std::pair<std::string, double>> truth{{"white", N}, {"gm1.sigma", s1}, {"gm1.tau", T1}};
      if (withRw) truth.push_back({"random_walk", std::stod(std::to_string(K))});
      for (const auto& [name, v] : truth) {
        const auto& p = f.parameter(name);
        ++checks;
        covered += std::fabs(p.value - v) <= 2.0 * p.stdError ? 1 : 0;
      }
    }
  INFO("right sets " << right << "/" << total << ", covered " << covered << "/" << checks);
  CHECK(right >= 13);
  CHECK(covered >= 0.9 * checks);
}

TEST_CASE("latent fit: the white density's 1 sigma holds for a GM sampled or averaged over each interval",
          "[fit][latent]") {
  // An integrating sensor outputs the mean of a continuous GM over each interval (the simulator's
  // GM without `rate:`); the fit writes a sampled AR(1). Their Allan variances differ at short tau
  // by ~ sigma^2 dt / (3 T tau), white noise's shape, so the white density absorbs it: here
  // dN^2 / N^2 = sigma^2 dt^2 / (3 T N^2) = 1.9 % (1.0 % in N), several of its 1-sigma at 100 Hz,
  // 20 min (GM tau 25 samples). The record cannot tell the two apart (both fit alike), so the
  // stated 1-sigma includes the shift (LatentParameter::gmConventionShift): the truth is covered
  // at 2 sigma whichever the record holds. 10 seeds each; without the shift in the 1-sigma the
  // averaged records are covered in 0-3 of 10.
  const double rate = 100.0, duration = 1200.0, N = 1e-3, sigma = 0.012, T = 0.25;
  for (const char* convention : {"", ", rate: 100 Hz"}) {
    char body[256];
    std::snprintf(body, sizeof body,
                  "gyro:\n  x:\n    - {type: white, density: %g rad/sqrt(s)}\n"
                  "    - {type: gauss_markov, sigma: %g rad/s, tau: %g s%s}\n",
                  N, sigma, T, convention);
    int covered = 0, right = 0;
    double shift = 0.0;
    for (int s = 0; s < 10; ++s) {
      const auto r = identify_test::staticRecord(body, rate, duration, 7100 + std::uint64_t(s));
      LatentFitOptions o;
      o.sampleInterval = 1.0 / rate;
      const LatentFit f = fitLatentModel(r.gyro[0], o);
      if (!(f.terms == LatentTermSet{false, true, 1, false, false, false})) continue;
      ++right;
      const LatentParameter& w = f.parameter("white");
      covered += std::fabs(w.value - N) <= 2.0 * w.stdError ? 1 : 0;
      shift += w.gmConventionShift / w.value;
    }
    shift /= std::max(right, 1);
    INFO("GM" << (*convention ? " sampled" : " averaged") << ": right sets " << right << "/10, white covered "
              << covered << ", mean shift " << shift);
    CHECK(right >= 9);
    CHECK(covered >= right - 1);
    // The shift is the closed form's: N_averaged / N_sampled - 1 = sqrt(1 + dN^2 / N^2) - 1 ~ +1 %
    CHECK(shift == Approx(std::sqrt(1.0 + sigma * sigma / (rate * rate * 3.0 * T * N * N)) - 1.0).epsilon(0.15));
  }
}

namespace {

/// White noise (density N) plus digital flicker noise sampled at each instant, one-sided PSD
/// B^2 / (pi f) from 1/(n dt) to Nyquist by spectral synthesis (FFTW): the n dt-periodic sum of
/// cosines whose bin k has variance B^2 / (pi k) - how generators outside sinsim make 1/f noise.
std::vector<double> whitePlusSampledFlicker(double N, double B, double dt, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> z(0.0, 1.0);
  std::vector<double> x(n);
  fftw_complex* c = fftw_alloc_complex(n / 2 + 1);
  fftw_plan plan = fftw_plan_dft_c2r_1d(int(n), c, x.data(), FFTW_ESTIMATE);
  c[0][0] = c[0][1] = c[n / 2][0] = c[n / 2][1] = 0.0;
  for (std::size_t k = 1; k < n / 2; ++k) {
    const double sd = std::sqrt(B * B / (sinsim::kPi * double(k)));
    c[k][0] = 0.5 * sd * z(rng), c[k][1] = -0.5 * sd * z(rng);  // x_t = sum A cos + B sin
  }
  fftw_execute(plan);
  fftw_destroy_plan(plan);
  fftw_free(c);
  for (double& v : x) v += N / std::sqrt(dt) * z(rng);
  return x;
}

}  // namespace

TEST_CASE("latent fit: the white density's 1 sigma holds for a flicker sampled at each instant",
          "[fit][latent]") {
  // The fit's flicker is the flat Allan floor, the averaged 1/f process; digital 1/f noise sampled
  // at each instant has 1.19x the floor at tau = dt, 1.09x at 2 dt (flickerSampledAllanVariance),
  // which the white density absorbs: here ~2 % of the white Allan variance at tau = dt (the floor
  // crosses the white at 0.1 s), several of the white's 1-sigma at 2^17 samples. The record cannot
  // tell the two apart, so the 1-sigma includes the shift (flickerConventionShift, negative for
  // the white: the sampled form carries that short-tau power itself). 10 seeds at 100 Hz; without
  // the shift in the 1-sigma the white is covered in 1-3 of 10.
  const double dt = 0.01, N = 1e-3, B = N / std::sqrt(0.1 * 2.0 * std::log(2.0) / sinsim::kPi);
  int right = 0, covered = 0, negative = 0;
  for (int s = 0; s < 10; ++s) {
    LatentFitOptions o;
    o.sampleInterval = dt;
    const LatentFit f = fitLatentModel(whitePlusSampledFlicker(N, B, dt, std::size_t(1) << 17, 7200 + s), o);
    if (!(f.terms == LatentTermSet{false, true, 0, true, false, false})) continue;
    ++right;
    const LatentParameter& w = f.parameter("white");
    covered += std::fabs(w.value - N) <= 2.0 * w.stdError ? 1 : 0;
    negative += w.flickerConventionShift < 0.0 ? 1 : 0;
  }
  INFO("right sets " << right << "/10, white covered " << covered << ", shift negative " << negative);
  CHECK(right >= 8);
  CHECK(covered >= right - 1);
  CHECK(negative == right);
}

TEST_CASE("latent fit with an AR term recovers AR + slow terms from their exact Allan variance",
          "[fit][latent][ar]") {
  const double dt = 0.01;
  const std::size_t N = 120000;  // 20 min at 100 Hz
  const auto m = octaves(N);
  // The seed paper's gx AR(5) polynomial, E such that the long-tau white density is 5.8e-5.
  const std::vector<double> a{1.0, -1.0327, -0.34341, 0.037895, 0.19732, 0.14724};
  double a1 = 0.0;
  for (double v : a) a1 += v;
  LatentModel base;
  base.arPolynomial = a;
  base.arVariance = 5.8e-5 * 5.8e-5 * a1 * a1 / dt;
  LatentModel rw = base;
  rw.randomWalk = 2.9e-5;
  LatentModel gm = base;
  gm.gm = {{3.5e-5, 20.0}};
  LatentModel fl = base;
  fl.flicker = 1.5e-5;
  LatentFitOptions o;
  o.sampleInterval = dt;
  o.arPolynomial = a;
  for (const auto& truth : {rw, gm, fl, base}) {
    INFO(truth.termNames());
    o.candidates.clear();
    for (int g = 0; g <= 1; ++g)
      for (int k = 0; k <= 1; ++k)
        for (int b = 0; b <= 1; ++b) {
          LatentTermSet s{false, false, g, b == 1, k == 1, false};
          s.ar = true;
          o.candidates.push_back(s);
        }
    o.minGmTauSamples = 100.0;  // slow GMs only (fit/ar_slow_fit.hpp: 10 T_c)
    const LatentFit f = fitLatentModel(m, latentAllanVariance(truth, dt, m), N, o);
    CHECK(f.model.termNames() == truth.termNames());
    // Exact data: golden-section tolerance on tau and NNLS round-off only (as above).
    CHECK(f.model.arVariance == Approx(truth.arVariance).epsilon(1e-4));
    CHECK(f.model.randomWalk == Approx(truth.randomWalk).epsilon(1e-4).margin(1e-12));
    CHECK(f.model.flicker == Approx(truth.flicker).epsilon(1e-4).margin(1e-12));
    REQUIRE(f.model.gm.size() == truth.gm.size());
    if (!truth.gm.empty()) CHECK(f.model.gm[0].tau == Approx(truth.gm[0].tau).epsilon(1e-4));
    CHECK(f.chi2 < 1e-6);
    CHECK(f.parameter("ar.sigma").value == Approx(std::sqrt(truth.arVariance)).epsilon(1e-4));
  }
  o.arPolynomial.clear();  // a set with an AR term needs its polynomial
  CHECK_THROWS_AS(fitLatentModel(m, latentAllanVariance(base, dt, m), N, o), sinsim::InputError);
}

TEST_CASE("latent fit's intervals: the union of the delta method's and the ln one",
          "[fit][latent]") {
  // covers(): |truth - value| <= k stdError, or (logScale) -k logLower <= ln truth - logCenter
  // <= k logUpper (closed form of the bounds at k = 2: linear 1.2..2.8, profile 1.213..8.963).
  const LatentParameter tau{"gm1.tau", 2.0, 0.4, true, std::log(2.0), 0.25, 0.75};
  CHECK(tau.covers(2.0 * std::exp(1.499), 2.0));        // the profile's upper side
  CHECK_FALSE(tau.covers(2.0 * std::exp(1.501), 2.0));
  CHECK(tau.covers(2.0 * std::exp(-0.499), 2.0));       // the profile's lower side (1.213)
  CHECK(tau.covers(1.2001, 2.0));                       // the linear lower side (1.2) is longer
  CHECK_FALSE(tau.covers(1.1999, 2.0));
  CHECK_FALSE(tau.covers(0.0, 2.0));
  const LatentParameter white{"white", 2.0, 1.0};  // no ln interval: the linear one alone
  CHECK(white.covers(3.999, 2.0));
  CHECK_FALSE(white.covers(4.001, 2.0));
  CHECK(white.covers(0.001, 2.0));
  // An amplitude's ln interval is symmetric in ln (K = 1, sd 0.3, ln sd 0.3; at k = 2 linear
  // 0.4..1.6, ln e^-0.6..e^0.6 = 0.549..1.822): the ln side is the longer one above, the linear below.
  const LatentParameter walk{"random_walk", 1.0, 0.3, true, 0.0, 0.3, 0.3};
  CHECK(walk.covers(std::exp(0.599), 2.0));
  CHECK_FALSE(walk.covers(std::exp(0.601), 2.0));
  CHECK(walk.covers(0.4001, 2.0));
  CHECK_FALSE(walk.covers(0.3999, 2.0));
}

TEST_CASE("latent fit's profile-likelihood interval of a slow GM's tau covers it", "[fit][latent]") {
  // White + GM records (std::mt19937_64, the exact AR(1) at dt: not sinsim's effects), 100 Hz,
  // 2^16 samples (655 s); the GM's tau of 20 s puts its hump (~1.9 T = 38 s) in the last octaves
  // of the Allan range (<= N dt / 10 = 41 s on the octave grid), where T's estimate is skewed
  // low (a short T moves the hump into the points, a long one out of them) and the linear
  // value +- 2 sigma misses above. The set is fixed (white + GM): the interval alone is tested.
  // Bound: issue 11's 90 % floor, 108 of 120 seeds (at the nominal 95.4 %: 114.5 expected, sd
  // 2.3, the bound 2.8 sd below). Measured: the stated interval (the union of the linear and the
  // ln-T profile ones) 112/120, the profile's alone 111/120 (misses 8 above, 1 below); the linear
  // value +- 2 sigma alone 106/120 (14 above) would fail.
  const double dt = 0.01, N0 = 5.8e-5, sigma = 8.7e-5, T = 20.0;
  const std::size_t n = std::size_t(1) << 16;
  const double phi = std::exp(-dt / T), drive = sigma * std::sqrt(1.0 - phi * phi);
  LatentFitOptions o;
  o.sampleInterval = dt;
  o.candidates = {LatentTermSet{false, true, 1, false, false, false}};
  int covered = 0, above = 0, linearCovered = 0;
  const int seeds = 120;
  for (int s = 0; s < seeds; ++s) {
    std::mt19937_64 rng(9100 + std::uint64_t(s));
    std::normal_distribution<double> g;
    std::vector<double> x(n);
    double b = sigma * g(rng);
    for (auto& v : x) {
      b = phi * b + drive * g(rng);
      v = b + N0 / std::sqrt(dt) * g(rng);
    }
    const LatentAllanPoints a = latentAllanPoints(x, dt);
    const LatentParameter t = fitLatentModel(a.m, a.avar, n, o).parameter("gm1.tau");
    REQUIRE(t.logScale);
    REQUIRE(t.logCenter == Approx(std::log(t.value)).epsilon(1e-12));
    REQUIRE(t.logLower > 0.0);
    REQUIRE(t.logUpper > 0.0);
    covered += t.covers(T, 2.0);
    above += !t.covers(T, 2.0) && T > t.value;
    linearCovered += std::fabs(t.value - T) <= 2.0 * t.stdError;
  }
  INFO("stated interval (linear or profile in ln T): covered " << covered << "/" << seeds << " (misses above " << above
                                            << "); linear value +- 2 sigma: " << linearCovered << "/" << seeds);
  CHECK(covered >= 108);
}

TEST_CASE("latent fit's ln intervals stay finite when the other discretisation moves a parameter far",
          "[fit][latent]") {
  // White + a weak GM (its hump under the white noise) + a walk, 100 Hz, 20 min (std::mt19937_64,
  // the exact AR(1): not sinsim's effects). In some sets the GM's tau is hardly bounded and the
  // other discretisation (sampled / averaged, LatentParameter::gmConventionShift) moves it by
  // factors of 10-100; its ln interval widens by ln(v_other / v). The first-order shift / v
  // stated 1-sigma intervals of e^-100..e^100 times the value on 3 of 12 such records (1e-105 s
  // .. 4e109 s). The profile is capped at e^8 on each side and the tau range spans less than
  // e^15, so no stated ln half-width of a tau beyond 25 is a 1-sigma. (Seeds 0-23 of this record
  // with the old formula: half-widths 1149 and 60 on seeds 18 and 23, at most 8.1 on the others;
  // with ln(v_other / v) at most 8.4.)
  const double dt = 0.01, N0 = 1e-3, sigma = 2e-4, T = 5.0, K = 2e-5;
  const std::size_t n = 120000;
  const double phi = std::exp(-dt / T), drive = sigma * std::sqrt(1.0 - phi * phi);
  LatentFitOptions o;
  o.sampleInterval = dt;
  double widest = 0.0;
  std::string where;
  for (int s = 18; s < 24; ++s) {  // of seeds 0-23 the old first-order shift failed on 18 and 23
    std::mt19937_64 rng(9300 + std::uint64_t(s));
    std::normal_distribution<double> g;
    std::vector<double> x(n);
    double b = sigma * g(rng), walk = 0.0;
    for (auto& v : x) {
      b = phi * b + drive * g(rng);
      walk += K * std::sqrt(dt) * g(rng);
      v = b + walk + N0 / std::sqrt(dt) * g(rng);
    }
    const LatentFit f = fitLatentModel(x, o);
    auto note = [&](const std::string& name, bool logScale, double lower, double upper) {
      // A tau's interval: the profile's (capped) and the shift. (An amplitude's is a Wald interval
      // in ln, which an unidentified term's may make as wide as the data leave it.)
      if (!logScale || name.find(".tau") == std::string::npos) return;
      REQUIRE(std::isfinite(lower));
      REQUIRE(std::isfinite(upper));
      if (std::max(lower, upper) > widest) widest = std::max(lower, upper), where = name + ", seed " + std::to_string(s);
    };
    for (const auto& p : f.parameters) note(p.name, p.logScale, p.logLower, p.logUpper);
    for (const auto& a : f.averaged) note(a.name + " (averaged)", a.logScale, a.logLower, a.logUpper);
  }
  INFO("widest ln half-width " << widest << " (" << where << ")");
  CHECK(widest <= 25.0);
}

// A drift's Allan variance R^2 tau^2 / 2 shows only in the last octaves (tau <= T / 10), where it
// trades with a walk: there its 2-sigma covered R in 37/50 seeds of the round-trip study
// (generate.py --case white+rw+drift, 100 Hz, 20 min; docs/fitting.md). The record's trend holds
// the ramp: the GLS slope of the block means under the other terms (drift_gls.hpp), 49/50. Here
// white + random walk + a ramp of either sign at 100 Hz, 10 min, 16 seeds: the drift chosen in
// >= 14, its sign right on every one, its 2 sigma covering R in >= 90 % of them and the mean of
// z^2 = ((estimate - R) / sigma)^2 at most 2 (chi^2 over ~16 dof: 1 +- 0.35), so the stated 1
// sigma is neither too small nor a wide net.
TEST_CASE("latent fit: a drift's size and sign are the record's GLS trend beside a walk", "[fit][latent]") {
  const double rate = 100.0, duration = 600.0;
  const double N = 0.2 * sinsim::kRadPerDeg / 60.0, K = 200.0 * N / duration;
  const double R = std::sqrt(8.0 / 3.0) * K / std::sqrt(duration / 10.0);  // rad/s^2
  int chosen = 0, covered = 0, total = 0;
  double z2 = 0.0;
  for (std::uint64_t seed = 0; seed < 16; ++seed) {
    const double sign = seed % 2 ? -1.0 : 1.0;
    char body[512];
    std::snprintf(body, sizeof body,
                  "gyro:\n  x:\n    - {type: white, density: %.10g rad/sqrt(s)}\n"
                  "    - {type: random_walk, K: %.10g rad/s/sqrt(s)}\n    - {type: ramp, slope: %.10g rad/s/s}\n",
                  N, K, sign * R);
    const auto r = identify_test::staticRecord(body, rate, duration, 7300 + seed);
    LatentFitOptions o;
    o.sampleInterval = 1.0 / rate;
    const LatentFit f = fitLatentModel(r.gyro[0], o);
    ++total;
    if (!f.terms.drift) continue;
    ++chosen;
    const auto& p = f.parameter("drift");
    INFO("seed " << seed << ": set " << f.terms.name() << ", drift " << p.value << " +- " << p.stdError
                 << " (true " << R << "), signed slope " << f.driftSlope);
    CHECK(f.driftSlope * sign > 0.0);
    CHECK(f.model.drift == Approx(p.value).epsilon(1e-12));
    const double z = (p.value - R) / p.stdError;
    covered += std::fabs(z) <= 2.0;
    z2 += z * z;
  }
  INFO("drift chosen " << chosen << "/" << total << ", covered " << covered << ", mean z^2 " << z2 / chosen);
  CHECK(chosen >= 14);
  CHECK(covered >= 0.9 * chosen);
  CHECK(z2 / chosen <= 2.0);
}

// A ramp under a GM's tail: white + GM (tau 3 s) + a ramp whose Allan variance at the top octave
// (tau = 120 s) is a third of the GM's there. The Allan fit of white + GM + drift puts the drift
// at zero, yet the record's trend holds it at ~7 sigma (the GLS slope's sd under white + GM:
// sqrt(12 S0 / T^3), S0 = N^2 + 2 sigma^2 T_gm). The block likelihood's slope test chooses the
// drift; it used to be dropped for want of a valid Allan fit (right set 66/100 in the study's
// white+gm+drift cell at 2 h, the same proportions; 100/100 with the drift from the trend,
// docs/fitting.md). 12 seeds, either sign: the drift chosen in >= 10 (11 now, 7 before), its sign
// right, its 2 sigma covering R in >= 9 (11 now).
TEST_CASE("latent fit: a ramp the Allan variance cannot hold beside a GM is taken from the trend", "[fit][latent]") {
  const double rate = 100.0, duration = 1200.0;
  const double N = 0.2 * sinsim::kRadPerDeg / 60.0, s1 = 0.005 * sinsim::kRadPerDeg, T1 = 3.0;
  const double R = std::sqrt(8.0) * N * std::pow(duration / 10.0, -1.5);  // rad/s^2
  int chosen = 0, covered = 0;
  for (std::uint64_t seed = 0; seed < 12; ++seed) {
    const double sign = seed % 2 ? -1.0 : 1.0;
    char body[512];
    std::snprintf(body, sizeof body,
                  "gyro:\n  x:\n    - {type: white, density: %.10g rad/sqrt(s)}\n"
                  "    - {type: gauss_markov, sigma: %.10g rad/s, tau: %.10g s, rate: 100 Hz}\n"
                  "    - {type: ramp, slope: %.10g rad/s/s}\n",
                  N, s1, T1, sign * R);
    const auto r = identify_test::staticRecord(body, rate, duration, 7400 + seed);
    LatentFitOptions o;
    o.sampleInterval = 1.0 / rate;
    const LatentFit f = fitLatentModel(r.gyro[0], o);
    INFO("seed " << seed << ": set " << f.terms.name() << ", drift from the trend alone " << f.trendDrift);
    if (!f.terms.drift) continue;
    ++chosen;
    const auto& p = f.parameter("drift");
    INFO("drift " << p.value << " +- " << p.stdError << " (true " << R << "), signed slope " << f.driftSlope);
    CHECK(f.driftSlope * sign > 0.0);
    covered += std::fabs(p.value - R) <= 2.0 * p.stdError;
  }
  INFO("drift chosen " << chosen << "/12, covered " << covered);
  CHECK(chosen >= 10);
  CHECK(covered >= 9);
}

TEST_CASE("latent fit: on a correlated value lattice the block means' slope test adds a ramp, rarely a false one",
          "[fit][latent]") {
  // White noise (+ a GM) each sample rounded on an LSB 1.5x its sd: the lattice's rounding is
  // correlated, so the Allan points choose the set (no block likelihood), and the drift is decided
  // by the slope test that likelihood makes, slope^2 / var > 6.63 (chi^2_1, 1 %). A ramp at 6 sd
  // of the GLS slope (var 12 S0 / T^3, S0 = N^2 + 2 sigma^2 tau the noise's density at zero
  // frequency) is found; without one the test passes in ~1 % of records (binomial: P(>= 4 of 40)
  // = 0.8 %).
  const double rate = 100.0, duration = 1200.0, dt = 1.0 / rate;
  const double N = 2e-4, sd = N / std::sqrt(dt), lsb = 1.5 * sd, sigma = 0.3 * sd, tau = 2.0;
  const double R = 6.0 * std::sqrt(12.0 * (N * N + 2.0 * sigma * sigma * tau) / std::pow(duration, 3.0));
  auto fitted = [&](std::uint64_t seed, double slope) {
    char body[512];
    std::snprintf(body, sizeof body,
                  "gyro:\n  x:\n    - {type: white, density: %.10g rad/sqrt(s)}\n"
                  "    - {type: gauss_markov, sigma: %.10g rad/s, tau: %.10g s, rate: 100 Hz}\n"
                  "    - {type: ramp, slope: %.10g rad/s/s}\n"
                  "    - {type: quantization, lsb: %.10g rad/s}\n",
                  N, sigma, tau, slope, lsb);
    const auto r = identify_test::staticRecord(body, rate, duration, seed);
    LatentFitOptions o;
    o.sampleInterval = dt;
    o.lattice.step = lsb * dt;
    return fitLatentModel(r.gyro[0], o);
  };
  int falseDrifts = 0, found = 0;
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    const LatentFit f = fitted(9100 + seed, 0.0);
    INFO("null seed " << seed << ": " << f.terms.name());
    falseDrifts += f.terms.drift;
  }
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    const double sign = seed % 2 ? -1.0 : 1.0;
    const LatentFit f = fitted(9200 + seed, sign * R);
    INFO("ramp seed " << seed << ": " << f.terms.name() << ", slope " << f.driftSlope << " (true " << sign * R << ")");
    if (f.terms.drift && f.driftSlope * sign > 0.0) ++found;
  }
  INFO("false drifts " << falseDrifts << "/40, ramps found " << found << "/10");
  CHECK(falseDrifts <= 3);
  CHECK(found >= 9);
}

TEST_CASE("latent fit warns about a GM tau pinned at a bound of its search range", "[fit][latent]") {
  // 20 min at 100 Hz: the GM is searched up to the largest Allan tau (N dt / 10 = 120 s at most).
  // A GM of tau 2000 s (a walk over the record) is pinned at the top; its tau is a bound.
  const double dt = 0.01;
  const std::size_t N = 120000;
  const auto m = octaves(N);
  LatentFitOptions o;
  o.sampleInterval = dt;
  o.candidates = {{false, true, 1, false, false, false}};
  LatentModel slow;
  slow.white = 5.8e-5;
  slow.gm = {{2e-3, 2000.0}};
  const LatentFit f = fitLatentModel(m, latentAllanVariance(slow, dt, m), N, o);
  std::string all;
  for (const auto& w : f.warnings) all += w + "\n";
  INFO(all);
  CHECK(all.find("sits at the highest tau searched") != std::string::npos);
  LatentModel ok;
  ok.white = 5.8e-5;
  ok.gm = {{2e-4, 2.0}};
  for (const auto& w : fitLatentModel(m, latentAllanVariance(ok, dt, m), N, o).warnings)
    CHECK(w.find("sits at") == std::string::npos);
}
