#include "tests/report/sample_report.hpp"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace sinsim::report::testing {
namespace {

// Seeded normal deviates from a 64-bit LCG (Knuth MMIX constants) and Box–Muller: the same bytes
// on every platform, unlike std::normal_distribution whose algorithm is implementation-defined.
class Noise {
 public:
  explicit Noise(std::uint64_t seed) : s_(seed) {}
  double uniform() {
    s_ = s_ * 6364136223846793005ULL + 1442695040888963407ULL;
    return (static_cast<double>(s_ >> 11) + 0.5) / 9007199254740992.0;  // (0, 1)
  }
  double normal() {
    const double u1 = uniform(), u2 = uniform();
    return std::sqrt(-2 * std::log(u1)) * std::cos(6.283185307179586 * u2);
  }

 private:
  std::uint64_t s_;
};

std::vector<double> logspace(double a, double b, int n) {
  std::vector<double> v(n);
  for (int i = 0; i < n; ++i) v[i] = a * std::pow(b / a, static_cast<double>(i) / (n - 1));
  return v;
}

}  // namespace

HtmlPage samplePage() {
  Noise noise(20240601);
  HtmlPage page("Sample sinsim report — gyro X diagnosis & Monte Carlo");
  page.paragraph("Synthetic example of every report element. Model: angle random walk "
                 "N = 0.15 deg/√h, bias instability B = 1.2 deg/h, rate random walk K = 4 deg/h/√h; "
                 "the \"measurement\" adds a 0.4 deg/h sinusoid near τ = 30 s.");

  // --- Allan deviation, log-log, IEEE Std 952-1997 eq. C.2 closed forms -------------------------
  const double N = 0.15 * 60, B = 1.2, K = 4.0 / 60;  // deg/h·√s, deg/h, deg/h/√s
  const double T = 4 * 3600.0;                           // record length [s]
  const std::vector<double> tau = logspace(0.01, 3000, 60);
  Series model{"model", {}, {}, "#ff7f0e", false, 2.2, false};
  Series meas{"measurement", {}, {}, "#1f77b4", false, 1.6, true};
  Series before{"model before fit", {}, {}, "#7f7f7f", true, 1.6, false};
  Band band{"model 95 % band", {}, {}, {}, "#ff7f0e", 0.2};
  for (double t : tau) {
    const double s2 = N * N / t + 2 * std::log(2.0) / M_PI * B * B + K * K * t / 3;
    const double s = std::sqrt(s2);
    // Relative 1σ error of an overlapping Allan deviation ≈ 1/√(2(T/τ − 1)) (IEEE 952 eq. C.6).
    const double rel = 1 / std::sqrt(2 * (T / t - 1));
    const double bump = 0.4 * std::exp(-std::pow(std::log10(t / 30), 2) / 0.08);
    model.x.push_back(t);
    model.y.push_back(s);
    band.x.push_back(t);
    band.lo.push_back(s * (1 - 1.96 * rel));  // may go ≤ 0 at long τ: dropped on the log axis
    band.hi.push_back(s * (1 + 1.96 * rel));
    meas.x.push_back(t);
    meas.y.push_back(std::sqrt(s2 + bump * bump) * (1 + rel * noise.normal()));
    before.x.push_back(t);
    before.y.push_back(std::sqrt(1.6 * N * N / t + 0.5 * B * B));
  }
  Plot adev("Allan deviation — gyro X", "averaging time τ [s]", "σ(τ) [deg/h]");
  adev.xLog = adev.yLog = true;
  adev.add(band).add(before).add(model).add(meas);
  adev.add(Shade{12, 80, "#d62728", "outside the 95 % band", 0.12});
  adev.add(Shade{1500, 3000, "#d62728", "outside the 95 % band", 0.12});
  page.heading("Diagnosis: gyro X");
  page.plot(adev, "Shaded τ-ranges: measurement outside the model's 95 % band. Dashed: model "
                  "before the fit.");

  Table findings;
  findings.caption = "Findings";
  findings.header = {"τ-range [s]", "worst ratio meas/model", "z-score", "verdict"};
  findings.rows.push_back({"0.01 – 12", Cell("1.02", "num"), Cell("0.4", "num"), Cell("ok", "pass")});
  findings.rows.push_back(
      {"12 – 80", Cell("1.38", "num fail"), Cell("6.1", "num fail"), Cell("unmodelled periodic term", "fail")});
  findings.rows.push_back(
      {"80 – 1500", Cell("0.97", "num"), Cell("−0.8", "num"), Cell("ok", "pass")});
  findings.rows.push_back({"1500 – 3000", Cell("1.21", "num warn"), Cell("2.2", "num warn"),
                           Cell("few clusters; weak evidence", "warn")});
  page.table(findings);

  // --- PSD and ACF side by side --------------------------------------------------------------------
  Plot psd("Power spectral density", "frequency f [Hz]", "S(f) [(deg/h)²/Hz]");
  psd.xLog = psd.yLog = true;
  Series psdMeas{"Welch estimate", {}, {}, "", false, 1.2, false};
  Series psdModel{"model", {}, {}, "", false, 2.2, false};
  for (double f : logspace(1e-4, 50, 400)) {
    const double S = N * N * 3600 / 3600 + K * K / (4 * M_PI * M_PI * f * f) + B * B * 0.1 / f;
    psdModel.x.push_back(f);
    psdModel.y.push_back(S);
    psdMeas.x.push_back(f);
    psdMeas.y.push_back(S * std::exp(0.35 * noise.normal()));
  }
  psd.add(psdMeas).add(psdModel);
  Plot acf("Autocorrelation", "lag [s]", "ρ");
  Series acfMeas{"measured", {}, {}, "", false, 1.5, false};
  Series acfModel{"Gauss–Markov, T = 40 s", {}, {}, "", true, 2, false};
  Band acfBand{"±2/√n", {}, {}, {}, "#7f7f7f", 0.18};
  for (int i = 0; i <= 300; ++i) {
    const double lag = i * 0.5;
    acfModel.x.push_back(lag);
    acfModel.y.push_back(std::exp(-lag / 40));
    acfMeas.x.push_back(lag);
    acfMeas.y.push_back(std::exp(-lag / 40) + 0.03 * noise.normal());
    acfBand.x.push_back(lag);
    acfBand.lo.push_back(-0.06);
    acfBand.hi.push_back(0.06);
  }
  acf.add(acfBand).add(acfMeas).add(acfModel);
  page.plotRow({psd, acf});

  // --- Monte Carlo drift envelopes -----------------------------------------------------------------
  page.heading("Monte Carlo: horizontal position error, 200 runs per model");
  Plot drift("Position error envelopes (mean ± 3σ)", "time [min]", "north error [m]");
  const char* names[] = {"tactical MEMS", "consumer MEMS", "navigation FOG"};
  const double growth[] = {1.0, 3.5, 0.12};
  std::vector<Plot> singles;
  for (int m = 0; m < 3; ++m) {
    Band env{std::string(names[m]) + " ±3σ", {}, {}, {}, paletteColor(m), 0.18};
    Series mean{std::string(names[m]) + " mean", {}, {}, paletteColor(m), false, 2, false};
    for (int i = 0; i <= 600; ++i) {
      const double t = i * 0.1;                       // [min]
      const double sigma = growth[m] * std::pow(t, 1.5) * 0.8;  // ∝ t^1.5: gyro ARW through Schuler-free region
      const double mu = 0.15 * growth[m] * t * t;
      env.x.push_back(t);
      env.lo.push_back(mu - 3 * sigma);
      env.hi.push_back(mu + 3 * sigma);
      mean.x.push_back(t);
      mean.y.push_back(mu);
    }
    drift.add(env);
    drift.add(mean);
    Plot single(names[m], "time [min]", "north error [m]");
    Band e2 = env;
    e2.label = "±3σ";
    Series m2 = mean;
    m2.label = "mean";
    single.add(e2).add(m2);
    singles.push_back(single);
  }
  page.plot(drift, "", 900, 460);
  page.plotRow(singles, 360, 300);

  Table diffs;
  diffs.caption = "Differences at t = 60 min (Welch t-test on 200 + 200 runs)";
  diffs.header = {"model A", "model B", "Δ RMS [m]", "p-value", "significant at 1 %"};
  diffs.rows.push_back({"tactical MEMS", "consumer MEMS", Cell("−3 742", "num"),
                        Cell("< 1e-12", "num"), Cell("yes", "fail")});
  diffs.rows.push_back({"tactical MEMS", "navigation FOG", Cell("1 011", "num"),
                        Cell("3.2e-9", "num"), Cell("yes", "fail")});
  diffs.rows.push_back({"consumer MEMS", "navigation FOG", Cell("4 753", "num"),
                        Cell("0.41", "num"), Cell("no", "pass")});
  page.table(diffs);
  page.preformatted("sinsim mc --scenario car.yaml --models a.yaml,b.yaml,c.yaml --runs 200 \\\n"
                    "    --seed 42 --out mc/   # <illustrative> & \"quoted\" 'text'");
  return page;
}

}  // namespace sinsim::report::testing
