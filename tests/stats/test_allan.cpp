// Allan-family deviations against Stable32 (independent tool, numbers committed in
// ../shared/data/ocxo-stable32) and against closed forms for synthetic power-law noise.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "errormodels/stats/allan.hpp"
#include "errormodels/stats/record.hpp"
#include "errormodels/stats/special.hpp"

using namespace sinsim::errormodels;

namespace {

const std::string kOcxoDir = std::string(SINSIM_SHARED_DIR) + "/data/ocxo-stable32/";

/// Fractional frequency y = f / 10 MHz - 1 of the OCXO record ('#' comment lines first).
std::vector<double> ocxoFractionalFrequency() {
  std::ifstream in(kOcxoDir + "ocxo_frequency.txt");
  REQUIRE(in.good());
  std::vector<double> y;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    // f [Hz] has 24 significant digits, more than a double holds: read the integer and the
    // fractional part apart so that y = (f - 1e7) / 1e7 keeps its digits (~1e-24 instead of
    // the 9.3e-17 a double f would give).
    const std::size_t dot = line.find('.');
    const double whole = std::stod(line.substr(0, dot));
    const double frac = dot == std::string::npos ? 0.0 : std::stod("0" + line.substr(dot));
    y.push_back(((whole - 1e7) + frac) / 1e7);
  }
  return y;
}

struct Stable32Row {
  std::size_t af, count;
  int alpha;
  double sigma;
  std::string sigma_text;
};

std::vector<Stable32Row> stable32Table(const std::string& file) {
  std::ifstream in(kOcxoDir + file);
  REQUIRE(in.good());
  std::vector<Stable32Row> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    Stable32Row r;
    double tau, min_sigma, max_sigma;
    ls >> r.af >> tau >> r.count >> r.alpha >> min_sigma >> r.sigma_text >> max_sigma;
    r.sigma = std::stod(r.sigma_text);
    rows.push_back(r);
  }
  return rows;
}

/// Half a unit of the last printed digit of a "%.4e" number: the value printed as 7.6106e-11
/// stands for anything within +-0.5e-15 of it.
double halfLastDigit(double printed) {
  const double e = std::floor(std::log10(std::abs(printed)));
  return 0.5 * std::pow(10.0, e - 4);
}

/// Runs one variant over every AF of a Stable32 table; every sigma must round to the printed 5
/// significant digits and every count must equal Stable32's "#". boundary_slack (relative)
/// widens the half-unit window for values that sit on a rounding boundary of the printed digit.
void checkAgainstStable32(AllanVariant variant, const std::string& file, double boundary_slack) {
  const std::vector<double> y = ocxoFractionalFrequency();
  REQUIRE(y.size() == 19982);
  const std::vector<Stable32Row> rows = stable32Table(file);
  REQUIRE(rows.size() > 200);
  AllanOptions opt;
  for (const auto& r : rows) opt.factors.push_back(r.af);
  opt.confidence_intervals = false;
  const AllanCurve c = allanDeviation(y, 1.0, variant, opt);
  REQUIRE(c.size() == rows.size());
  double worst = 0;  // in units of the last printed digit
  for (std::size_t i = 0; i < rows.size(); ++i) {
    INFO(file << " AF " << rows[i].af << ": ours " << c.dev[i] << ", Stable32 " << rows[i].sigma_text);
    CHECK(c.count[i] == rows[i].count);
    const double unit = 2 * halfLastDigit(rows[i].sigma);
    const double err = std::abs(c.dev[i] - rows[i].sigma) / unit;
    worst = std::max(worst, err);
    // Agreement to the printed digits: |ours - printed| <= half a unit of the last digit. The
    // 1e-9 units only absorb the binary representation of the printed decimal.
    CHECK(std::abs(c.dev[i] - rows[i].sigma) <= (0.5 + 1e-9) * unit + boundary_slack * c.dev[i]);
  }
  WARN(file << ": largest difference " << worst << " units of the 5th significant digit");
}

}  // namespace

TEST_CASE("overlapping ADEV reproduces Stable32 Sigma for every tau of the OCXO table", "[allan][stable32]") {
  // Strict: every one of the 282 values rounds to Stable32's printed 5 digits.
  checkAgainstStable32(AllanVariant::Overlapping, "stable32_oadev_alltau.txt", 0.0);
}

TEST_CASE("non-overlapping ADEV reproduces Stable32", "[allan][stable32]") {
  checkAgainstStable32(AllanVariant::NonOverlapping, "stable32_adev_alltau.txt", 0.0);
}

TEST_CASE("modified ADEV reproduces Stable32", "[allan][stable32]") {
  // One MDEV value (AF 1994) sits 1.4e-8 (relative) past a rounding boundary: ours
  // 6.99265014e-12, printed 6.9926e-12. An independent long-double evaluation of SP1065 eq. 14
  // (numpy, decimal-exact input) gives 6.9926501428e-12, so the difference is Stable32's own
  // rounding in its sums of ~14000 x 2000 terms; 1e-7 relative covers that and nothing more
  // (a wrong formula or count errs by >1e-3).
  checkAgainstStable32(AllanVariant::Modified, "stable32_mdev_alltau.txt", 1e-7);
}

TEST_CASE("Hadamard deviation reproduces Stable32", "[allan][stable32]") {
  checkAgainstStable32(AllanVariant::Hadamard, "stable32_hdev_alltau.txt", 0.0);
}

TEST_CASE("noise identification vs Stable32 Alpha column", "[allan][stable32][noiseid]") {
  const std::vector<double> y = ocxoFractionalFrequency();
  const std::vector<Stable32Row> rows = stable32Table("stable32_oadev_alltau.txt");
  AllanOptions opt;
  for (const auto& r : rows) opt.factors.push_back(r.af);
  const AllanCurve c = allanDeviation(y, 1.0, AllanVariant::Overlapping, opt);
  std::size_t compared = 0, same = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!c.alpha_measured[i]) continue;
    ++compared;
    if (c.alpha[i] == rows[i].alpha) ++same;
    else WARN("AF " << rows[i].af << ": alpha ours " << c.alpha[i] << ", Stable32 " << rows[i].alpha);
  }
  WARN("noise id agrees with Stable32 at " << same << " of " << compared << " tau");
  // Both use the lag-1 method (Stable32 switches to B1/R(n) below 30 points, where ours reports
  // alpha_measured = false and is not compared). The integer type is a rounded noisy statistic:
  // where rho sits near a rounding edge, detail differences (detrending) flip it, so ask 95 %.
  CHECK(compared >= 160);
  CHECK(same >= 0.95 * compared);
}

namespace {

/// Replicates of AVAR estimates of seeded power-law noise; returns the Monte Carlo EDF
/// 2 mean^2 / var (SP1065 eq. 44: var(s2) = 2 s2^2 / edf).
double monteCarloEdf(int alpha, AllanVariant variant, std::size_t n, std::size_t m, int reps,
                     double& greenhall) {
  std::mt19937_64 rng(20240607);  // stream "allan-edf"
  std::normal_distribution<double> g;
  std::vector<double> est;
  AllanOptions opt;
  opt.factors = {m};
  opt.alpha = alpha;
  for (int r = 0; r < reps; ++r) {
    std::vector<double> y(n);
    double walk = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double w = g(rng);
      if (alpha == 0) y[i] = w;                      // white FM
      else if (alpha == -2) y[i] = (walk += w);      // random-walk FM
    }
    if (alpha == 2) {  // white PM: y is the first difference of white phase
      std::vector<double> x(n + 1);
      for (auto& v : x) v = g(rng);
      for (std::size_t i = 0; i < n; ++i) y[i] = x[i + 1] - x[i];
    }
    const AllanCurve c = allanDeviation(y, 1.0, variant, opt);
    est.push_back(c.dev[0] * c.dev[0]);
    greenhall = c.edf[0];
  }
  double mean = 0, var = 0;
  for (double v : est) mean += v;
  mean /= reps;
  for (double v : est) var += (v - mean) * (v - mean);
  var /= reps - 1;
  return 2 * mean * mean / var;
}

}  // namespace

TEST_CASE("Greenhall EDF matches the Monte Carlo scatter of the estimator", "[allan][edf]") {
  // 3000 replicates: the Monte Carlo EDF 2 mean^2 / var has a relative standard error of about
  // sqrt(2/3000 * (1 + kurtosis terms)) ~ 3 %. Greenhall's unmodified-variance model (F = m,
  // phase averaged over tau0) is itself up to ~7 % below the EDF of point-sampled discrete
  // white FM at small m (checked with 40000 replicates: m = 10 gives 145 vs 135; the paper's
  // F = inf branch gives 146), which makes the intervals slightly conservative. 15 % covers
  // both and still fails for a wrong case (overlap gain ignored: a factor 2..10 at these m).
  struct Case {
    int alpha;
    AllanVariant v;
    std::size_t n, m;
  };
  const Case cases[] = {
      {0, AllanVariant::Overlapping, 1000, 10},   {0, AllanVariant::Overlapping, 1000, 100},
      {-2, AllanVariant::Overlapping, 1000, 20},  {2, AllanVariant::Overlapping, 1000, 8},
      {0, AllanVariant::NonOverlapping, 1000, 10}, {0, AllanVariant::Modified, 1000, 10},
      {0, AllanVariant::Hadamard, 1000, 10},      {-2, AllanVariant::OverlappingHadamard, 1000, 20},
  };
  for (const Case& k : cases) {
    double gh = 0;
    const double mc = monteCarloEdf(k.alpha, k.v, k.n, k.m, 3000, gh);
    INFO(toString(k.v) << " alpha " << k.alpha << " m " << k.m << ": Greenhall " << gh
                       << ", Monte Carlo " << mc);
    CHECK(mc == Approx(gh).epsilon(0.15));
  }
}

TEST_CASE("Greenhall EDF agrees with the SP1065 Table 5 approximations", "[allan][edf]") {
  // NIST SP1065 Table 5 (Howe, Allan, Barnes) for overlapping ADEV: empirical fits. Against
  // 40000-replicate Monte Carlo they are themselves ~5 % high for RW FM at m = 20 (47.2 vs
  // 44.8, where Greenhall gives 44.8), so agreement to 10 % at m >= 10 is what to expect.
  const double N = 10001;  // phase points
  for (double m : {10.0, 30.0, 100.0}) {
    const double wfm = (3 * (N - 1) / (2 * m) - 2 * (N - 2) / N) * (4 * m * m) / (4 * m * m + 5);
    CHECK(greenhallEdf(0, 2, m, N, true, false) == Approx(wfm).epsilon(0.10));
    const double wpm = (N + 1) * (N - 2 * m) / (2 * (N - m));
    CHECK(greenhallEdf(2, 2, m, N, true, false) == Approx(wpm).epsilon(0.10));
    const double rwfm = (N - 2) / (m * (N - 3) * (N - 3)) * ((N - 1) * (N - 1) - 3 * m * (N - 1) + 4 * m * m);
    CHECK(greenhallEdf(-2, 2, m, N, true, false) == Approx(rwfm).epsilon(0.10));
  }
  // Outside the estimable range: alpha + 2d <= 1.
  CHECK_THROWS_AS(greenhallEdf(-3, 2, 4, 1000, true, false), sinsim::InputError);
}

TEST_CASE("confidence intervals cover the true deviation at their stated rate", "[allan][edf]") {
  // White FM of unit variance: true OADEV at tau = m is 1/sqrt(m) (SP1065 Table 2).
  // 400 records, identified noise type, 68.3 % intervals: the coverage count is binomial,
  // sd = sqrt(400 * 0.683 * 0.317) = 9.3, so +-30 (3.2 sd) around 273.
  std::mt19937_64 rng(777);  // stream "allan-coverage"
  std::normal_distribution<double> g;
  AllanOptions opt;
  opt.factors = {1, 4, 16};
  int covered[3] = {0, 0, 0};
  for (int r = 0; r < 400; ++r) {
    std::vector<double> y(2000);
    for (auto& v : y) v = g(rng);
    const AllanCurve c = allanDeviation(y, 1.0, AllanVariant::Overlapping, opt);
    for (int i = 0; i < 3; ++i) {
      const double truth = 1.0 / std::sqrt(static_cast<double>(opt.factors[i]));
      if (c.lo[i] <= truth && truth <= c.hi[i]) ++covered[i];
    }
  }
  for (int i = 0; i < 3; ++i) {
    INFO("m = " << opt.factors[i] << ": covered " << covered[i] << " of 400");
    CHECK(std::abs(covered[i] - 273) <= 30);
  }
}

TEST_CASE("Allan deviation closed forms and edge cases", "[allan]") {
  // A constant rate has zero deviation at every tau (the mean is removed exactly).
  std::vector<double> flat(100, 3.25);
  AllanOptions noci;
  noci.confidence_intervals = false;
  const AllanCurve c = allanDeviation(flat, 10.0, AllanVariant::Overlapping, noci);
  REQUIRE(c.size() > 0);
  for (double d : c.dev) CHECK(d == 0.0);
  CHECK(c.tau[0] == Approx(0.1));
  // A linear ramp y = R t gives OADEV = R tau / sqrt(2) (SP1065 Table 2, drift), exactly.
  std::vector<double> ramp(1000);
  for (std::size_t i = 0; i < ramp.size(); ++i) ramp[i] = 0.5 * i;  // R = 0.5 per s at 1 Hz
  const AllanCurve r = allanDeviation(ramp, 1.0, AllanVariant::Overlapping, noci);
  for (std::size_t i = 0; i < r.size(); ++i) CHECK(r.dev[i] == Approx(0.5 * r.tau[i] / std::sqrt(2.0)).epsilon(1e-12));
  // Bad input.
  CHECK_THROWS_AS(allanDeviation({1.0, 2.0}, 1.0), sinsim::InputError);
  CHECK_THROWS_AS(allanDeviation(flat, 0.0), sinsim::InputError);
  CHECK_THROWS_AS(allanDeviation({1.0, NAN, 2.0, 3.0}, 1.0), sinsim::InputError);
  AllanOptions bad;
  bad.factors = {1, 60};  // > (N_x - 1) / 2 = 50
  CHECK_THROWS_AS(allanDeviation(flat, 1.0, AllanVariant::Overlapping, bad), sinsim::InputError);
  // Octave grid.
  CHECK(tauFactors(TauGrid::Octave, 10) == std::vector<std::size_t>{1, 2, 4, 8});
  CHECK(tauFactors(TauGrid::PerDecade, 10, 3) == std::vector<std::size_t>{1, 2, 5, 10});
}

TEST_CASE("ADIS16405 run 1 gyro x ADEV at 1 s is near the data note's 0.04 deg/s", "[allan][real]") {
  // Data README: "gyro ADEV at 1 s ~ 0.04 deg/s (ARW ~ 2.4 deg/sqrt(h))"; the datasheet ARW
  // 2.0 deg/sqrt(h) gives 2.0/60 = 0.033 deg/s. A loose band 0.025 .. 0.06 deg/s separates this
  // from a units slip (x57 for rad vs deg, x60 for per-sqrt(h)) or a wrong tau (x3 per decade).
  RecordOptions ro;
  ro.gyro_unit = "deg/s";
  ro.accel_unit = "g";
  ro.rate_hz = 100.0;
  const Record rec = loadRecord(std::string(SINSIM_SHARED_DIR) + "/data/adis16405/run1.csv.gz", ro);
  REQUIRE(rec.size() == 1000000);
  AllanOptions opt;
  opt.factors = {100};
  const AllanCurve c = allanDeviation(rec.gyro[0], rec.rate_hz, AllanVariant::Overlapping, opt);
  const double adev_dps = c.dev[0] * 180.0 / M_PI;
  WARN("ADIS16405 run1 gyro x OADEV(1 s) = " << adev_dps << " deg/s, 68% CI ["
       << c.lo[0] * 180 / M_PI << ", " << c.hi[0] * 180 / M_PI << "], edf " << c.edf[0]);
  CHECK(adev_dps > 0.025);
  CHECK(adev_dps < 0.06);
}
