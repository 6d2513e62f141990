// Diagnosis on records with a hidden effect (issue 5, "Must show").
//
// Every record is made by the synth machinery (ImuErrorModel realisation, diagnose::simulateRecord)
// from a TRUE model = base noise + one hidden effect. The base model is FITTED to the record by
// the identify pipeline (Burg AR, the paper's method) — it never sees the hidden effect's type.
// The fitted model is diagnosed; the hidden effect must come out first and be reported (score >=
// the threshold); --add of it must cut the misfit by at least half and leave >= 90 % of the tau
// inside the band. A record with nothing hidden must produce no reported finding.
//
// Base noise of gx (all tests): AR(2) at 100 Hz, A(z) = 1 - 1.2 z^-1 + 0.4 z^-2 (poles 0.6 +- 0.2i),
// driving sigma 0.02 deg/s, for 2000 s (N = 200 000): a correlated noise the paper's AR fit
// identifies, so the fitted base is right and only the hidden effect is missing. Hidden sizes are set to 3-10 x the base Allan deviation where
// their signature lives (the issue asks for detection, not for a detection-limit study; the
// null test below shows the threshold does not fire on the base alone).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "errormodels/diagnose/diagnose.hpp"
#include "errormodels/diagnose/series_tools.hpp"
#include "errormodels/identify.hpp"
#include "errormodels/imu_model.hpp"
#include "errormodels/model_io.hpp"
#include "errormodels/stats/special.hpp"
#include "test_support.hpp"

namespace dg = sinsim::errormodels::diagnose;
using sinsim::errormodels::ErrorModelSpec;
using sinsim::errormodels::errorModelFromString;
using sinsim::errormodels::Record;

namespace {

constexpr double kRate = 100.0;           // [Hz]
constexpr std::size_t kSamples = 200000;  // 2000 s

const std::string kBase =
    "gyro:\n"
    "  x:\n"
    "    - {type: ar, a: [-1.2, 0.4], sigma: 0.02 deg/s, rate: 100 Hz}\n";

dg::DiagnoseOptions options() {
  dg::DiagnoseOptions o;
  o.channels = {"gx"};
  o.realisations = 24;  // ln AVAR variances from 24 draws: +-29 % (chi2_23); enough for 5 sigma
  o.seed = 11;
  return o;
}

Record record(const std::string& hidden, std::uint64_t seed,
              const std::vector<double>& temperatureK = {}) {
  const std::string truth = kBase + hidden;
  // Earth rate and gravity are irrelevant to a static gyro-x record: ideal 0.
  return dg::simulateRecord(errorModelFromString(truth, "truth.yaml"), kRate, kSamples, seed, 0,
                            {0, 0, 0, 0, 0, 0}, temperatureK);
}

/// The base model as the identify pipeline fits it: Burg AR(2) on the record (hidden effect and all).
ErrorModelSpec fitBase(const Record& r) {
  sinsim::errormodels::IdentifyOptions io;
  io.axes = {"gx"};
  io.kind = sinsim::errormodels::IdentifyKind::Ar;
  io.order = 2;  // the base family's order (MDL picks 2 on the base record alone)
  // A base that lacks the hidden effect: fit would otherwise write a hidden line as a sinusoid.
  io.fitLines = false;
  const auto id = sinsim::errormodels::identify(r, io);
  auto spec = sinsim::errormodels::asWritten(id.modelSpec());  // as the fit's file holds it
  spec.source = "fitted.yaml";
  return spec;
}

void print(const dg::AxisDiagnosis& a) {
  std::cout << "  " << a.channel << " misfit " << a.misfit << ", outside " << a.fractionOutside
            << ", chi2 " << a.chi2 << "\n";
  for (const auto& f : a.findings)
    std::cout << "    " << f.effect << " score " << f.score << (f.reported ? " REPORTED " : " ")
              << f.size << "\n";
}

struct Outcome {
  dg::Improvement imp;
};

/// Diagnose the fitted base model, check the hidden effect(s) come out first, add them, check
/// the misfit falls.
Outcome diagnoseHidden(const std::string& name, const Record& r,
                       const std::vector<std::string>& hidden, bool requireHalving = true) {
  const auto base = fitBase(r);
  std::vector<dg::AddRequest> adds;
  for (const auto& h : hidden) adds.push_back(dg::AddRequest::parse(h + ":gx"));
  Outcome o{dg::improve(r, base, adds, options())};
  const auto& before = o.imp.before.axis("gx");
  const auto& after = o.imp.after.axis("gx");
  std::cout << name << ":\n";
  print(before);
  std::cout << " after adding:\n";
  print(after);
  // The hidden effects are the first |hidden| findings, and reported.
  REQUIRE(before.findings.size() >= hidden.size());
  for (std::size_t i = 0; i < hidden.size(); ++i) {
    INFO("finding " << i << ": " << before.findings[i].effect);
    CHECK(std::find(hidden.begin(), hidden.end(), before.findings[i].effect) != hidden.end());
    CHECK(before.findings[i].reported);
    CHECK(before.findings[i].score >= options().threshold);
  }
  // No false alarm beside them: nothing else reported (threshold 5.5, calibrated: docs/diagnose.md).
  std::size_t reported = 0;
  for (const auto& f : before.findings) reported += f.reported;
  CHECK(reported == hidden.size());
  if (requireHalving) CHECK(after.misfit <= 0.5 * before.misfit);
  // >= 90 % of the tau inside the 95 % band after the effect is added.
  CHECK(after.fractionOutside <= 0.10);
  return o;
}

/// `--add quantization:gx` to the model `base` (the true base, not a fit) on r, both diagnoses
/// printed; quantization must come first before.
dg::Improvement quantizationAdded(const Record& r, const std::string& base) {
  auto imp = dg::improve(r, errorModelFromString(base, "base.yaml"), {dg::AddRequest::parse("quantization:gx")},
                         options());
  print(imp.before.axis("gx"));
  print(imp.after.axis("gx"));
  REQUIRE_FALSE(imp.before.axis("gx").findings.empty());
  CHECK(imp.before.axis("gx").findings.front().effect == "quantization");
  return imp;
}

}  // namespace

TEST_CASE("hidden quantization is found from the value lattice and added", "[diagnose][hidden]") {
  // Increment LSB 0.0005 deg (rate lattice 0.05 deg/s, the ADIS16405 gyro LSB) carried: white-PM noise q^2/(4 tau^2).
  const auto r = record("    - {type: quantization, lsb: 0.0005 deg}\n", 101);
  auto o = diagnoseHidden("quantization", r, {"quantization"});
  const auto& f = o.imp.before.axis("gx").findings.front();
  // The lattice gives the LSB exactly (rate lattice = increment LSB / dt; the doubles' rounding
  // is ~1e-16 relative, 1e-9 leaves room for the median over differences).
  CHECK(f.params.at("lattice") == Approx(0.0005 * M_PI / 180 * kRate).epsilon(1e-9));
}

TEST_CASE("quantization on a lattice coarser than the noise is added without lowering the base", "[diagnose][hidden]") {
  // White noise of one-sample sd 0.5 deg/s at a cell's centre, rounded to an LSB of 2.5 deg/s
  // (5 sd): 98.8 % of the samples read 0, the rounding hides the noise (the challenge benchmark's
  // LSB-5 records). The model given is the true base. Adding the quantization must halve the
  // misfit: the simulator rounds exactly, so the base noise keeps its stated level (a level lowered
  // to help the Allan proxy of the rounding was rounded away again: misfit 0.24 -> 0.30 on such a
  // record before).
  const std::string base = "gyro:\n  x:\n    - {type: white, density: 0.05 deg/s/sqrt(Hz)}\n";
  const auto r = dg::simulateRecord(
      errorModelFromString(base + "    - {type: quantization, lsb: 2.5 deg/s}\n", "truth.yaml"), kRate,
      kSamples, 121, 0, {0, 0, 0, 0, 0, 0});
  const auto imp = quantizationAdded(r, base);
  const auto& before = imp.before.axis("gx");
  const auto& after = imp.after.axis("gx");
  CHECK(before.misfit > 0.1);
  CHECK(after.misfit <= 0.5 * before.misfit);
}

// A model that rounds each sample on a lattice coarser than its noise, compared with a record
// made by that very model at a level off its cell's centre: white noise of one-sample sd 0.5 deg/s
// at 0.75 deg/s, rounded to 2.5 deg/s, reads 2.5 in 16 % of the samples (P(Z > 1)) and averages
// 0.40 deg/s. Realised at that average — the record's mean, a rounded mean — the model reads 2.5
// in 4.5 % (P(Z > 1.7)): its variance 3.5x lower, far outside the band of its own kind of record.
// With a turn-on bias in the model (sd 5 deg/s, 2 LSB) each realisation's level falls elsewhere in
// its cell: flips from none to half the samples, a band too wide to say anything. Each realisation
// is rounded at the level whose rounded mean is the record's (the independent generator's r0446
// az, 4.7 LSB per sd: misfit 0.044 -> 0.088 after --add quantization before; the third
// generator's r0221 ay, with a turn-on bias: 0.139 -> 0.154).
TEST_CASE("a model that rounds each sample coarsely is realised where the sensor's level sat in its cell", "[diagnose]") {
  const std::string white = "gyro:\n  x:\n    - {type: white, density: 0.05 deg/s/sqrt(Hz)}\n";
  const std::string lattice = "    - {type: quantization, lsb: 2.5 deg/s}\n";
  const double level = 0.75 * M_PI / 180.0;  // [rad/s]
  for (const std::string& truth : {white + lattice, white + "    - {type: bias, sigma: 5 deg/s}\n" + lattice}) {
    for (std::uint64_t seed : {151, 152}) {
      const auto model = errorModelFromString(truth, "truth.yaml");
      const auto r = dg::simulateRecord(model, kRate, kSamples, seed, 0, {level, 0, 0, 0, 0, 0});
      const auto d = dg::diagnose(r, model, options()).axis("gx");
      print(d);
      for (const auto& f : d.findings) {
        INFO(f.effect << " score " << f.score);
        CHECK_FALSE(f.reported);
      }
      CHECK(d.misfit < 0.05);
      CHECK(d.fractionOutside <= 0.10);
      // A band that says something: at one sample a record this long pins the ADEV to a few %.
      INFO("band at one sample " << d.adev.lo.front() << " .. " << d.adev.hi.front());
      CHECK(d.adev.hi.front() < 1.2 * d.adev.lo.front());
    }
  }
}

// The same beside a true AR(2) base (kBase: one-sample ADEV ~0.016 deg/s, sd 0.042 deg/s), rounded
// to 0.08 deg/s (5x the one-sample ADEV: the challenge benchmark's coarsest LSB). A refit of the
// AR with the rounding noise's autocovariance taken out assumes that noise white and independent of
// the signal, which a lattice this coarse is not: the refit came out a factor off (misfit 0.075 ->
// 0.24, 96 % of tau outside on such a benchmark record). The AR given fits the Allan curve beside
// the rounding better than its refit, so it is kept.
TEST_CASE("a true AR base beside a coarse lattice is kept when quantization is added", "[diagnose][hidden]") {
  for (std::uint64_t seed : {141, 142}) {
    const auto r = record("    - {type: quantization, lsb: 0.08 deg/s}\n", seed);
    const auto imp = quantizationAdded(r, kBase);
    const auto& before = imp.before.axis("gx");
    const auto& after = imp.after.axis("gx");
    CHECK(before.fractionOutside > 0.2);
    CHECK(after.misfit < before.misfit);
    CHECK(after.fractionOutside <= 0.10);
    bool kept = false;
    for (const auto& n : imp.notes) kept = kept || n.find("base AR kept as given") != std::string::npos;
    CHECK(kept);
  }
}

// Quantization noise as GMWM (simts' QN) and IEEE Std 952 define it: the rate error
// sqrt(12) Q_r (U[k] - U[k-1]), U independent uniform on (0, 1) (test_support.hpp's
// addQuantizationNoise, not the simulator's streams), on no value lattice; ADEV at one sample
// sqrt(3) Q_r = 4x the base's. The model given is the true base (as in the challenge benchmark; a Burg AR(2) fitted to the record
// absorbs most of it: negative lag-1 correlation is what a low-order AR imitates). Found from the
// Allan slope -1 alone, nothing else reported, its LSB (sqrt(12) Q_r dt, an increment) within
// 10 %, written as the catalogue's dithered quantization; --add halves the misfit and leaves at most
// 10 % of the tau outside the band. (A refit of the base AR beside the added noise, which dominates
// the short-tau variance 4:1, came out a few % off and left 20-40 % outside; the true AR given fits
// better and is kept.)
TEST_CASE("quantization noise without a lattice (GMWM's QN) is found and added", "[diagnose][hidden]") {
  for (std::uint64_t seed : {131, 132}) {
    auto r = record("", seed);
    auto& y = r.gyro[0];
    double d2 = 0;
    for (std::size_t k = 1; k < y.size(); ++k) d2 += (y[k] - y[k - 1]) * (y[k] - y[k - 1]);
    const double adev1 = std::sqrt(0.5 * d2 / double(y.size() - 1));
    const double qRate = 4.0 * adev1 / std::sqrt(3.0);
    sinsim::test::addQuantizationNoise(y, qRate, seed);
    REQUIRE(sinsim::errormodels::latticeStep(y) == 0.0);
    const auto imp = quantizationAdded(r, kBase);
    const auto& before = imp.before.axis("gx");
    const auto& after = imp.after.axis("gx");
    const auto& f = before.findings.front();
    CHECK(f.reported);
    std::size_t reported = 0;
    for (const auto& g : before.findings) reported += g.reported;
    CHECK(reported == 1);
    CHECK(f.params.count("lattice") == 0);
    CHECK(f.params.at("lsb") == Approx(std::sqrt(12.0) * qRate / kRate).epsilon(0.10));
    CHECK_THAT(dg::effectText(f.spec, "gx"), Catch::Contains("dithered: true"));
    CHECK(after.misfit <= 0.5 * before.misfit);
    CHECK(after.fractionOutside <= 0.10);
  }
}

TEST_CASE("hidden random walk is found and added", "[diagnose][hidden]") {
  diagnoseHidden("random_walk", record("    - {type: random_walk, K: 0.0005 deg/s/sqrt(s)}\n", 102),
                 {"random_walk"});
}

TEST_CASE("hidden ramp is found and added", "[diagnose][hidden]") {
  // 900 deg/h^2 (0.5 deg/s over the 2000 s record, ~7x the base ADEV at tau = 1000 s). At
  // 300 deg/h^2 the ramp scores 7.4-8.4 against the threshold 8 (64 realisations, 6 comparison
  // seeds): a detection-limit case, pass or fail by the draw. At 600 deg/h^2 one comparison seed
  // in three ranks a slow warm-up above the ramp (over 2000 s the two shapes are close); at 900
  // the ramp comes first with score >= 13 for 3 records x 3 comparison seeds.
  diagnoseHidden("ramp", record("    - {type: ramp, slope: 900 deg/h^2}\n", 113), {"ramp"});
}

TEST_CASE("hidden bias instability is found and added", "[diagnose][hidden]") {
  diagnoseHidden("bias_instability",
                 record("    - {type: bias_instability, B: 0.004 deg/s, tau_range: [1 s, 1000 s]}\n", 104),
                 {"bias_instability"});
}

TEST_CASE("hidden sinusoid is found with its frequency and added", "[diagnose][hidden]") {
  auto o = diagnoseHidden("sinusoid",
                          record("    - {type: sinusoid, amplitude: 0.02 deg/s, frequency: 0.37 Hz}\n", 105),
                          {"sinusoid"});
  const auto& f = o.imp.before.axis("gx").findings.front();
  // Frequency resolution of a 1000 s record: 1 mHz; the refined peak is far better.
  CHECK(f.params.at("frequency") == Approx(0.37).margin(2e-4));
}

TEST_CASE("hidden temperature dependence is found and added", "[diagnose][hidden]") {
  std::vector<double> T(kSamples);
  for (std::size_t k = 0; k < kSamples; ++k)  // 25 degC +- 5 degC, period 400 s
    T[k] = 298.15 + 5 * std::sin(2 * M_PI * double(k) / kRate / 400.0);
  diagnoseHidden("temperature",
                 record("    - {type: temperature, T0: 25 degC, coefficients: [0.002 deg/s/degC]}\n", 106, T),
                 {"temperature"});
}

TEST_CASE("hidden warm-up is found and added", "[diagnose][hidden]") {
  diagnoseHidden("warmup", record("    - {type: warmup, amplitude: 0.1 deg/s, tau: 60 s}\n", 107),
                 {"warmup"});
}

TEST_CASE("hidden outliers are found and added", "[diagnose][hidden]") {
  diagnoseHidden("outliers", record("    - {type: outliers, rate: 0.05 Hz, amplitude: 1 deg/s}\n", 108),
                 {"outliers"}, /*requireHalving*/ false);
}

// With the selection by trial the line comes first, and the AR base is then re-estimated on the
// record without it: that AR (fitted to a record holding the random walk) takes part of the walk
// into a pole near 1, and what remains is as well explained by a slow GM (T = 41 s in a 2000 s
// record) as by more random walk. Both are the same physics over this record (a bias wandering
// over minutes); the test asks for the line first and a slow bias process second, reported, and
// the misfit halved by adding both (issue 12: telegraph-like or slow processes may come out as
// their physical equivalent).
TEST_CASE("two hidden effects on one axis come out first and second", "[diagnose][hidden]") {
  const auto r = record("    - {type: random_walk, K: 0.0005 deg/s/sqrt(s)}\n"
                        "    - {type: sinusoid, amplitude: 0.02 deg/s, frequency: 0.37 Hz}\n",
                        109);
  const auto base = fitBase(r);
  const auto d = dg::diagnose(r, base, options()).axis("gx");
  print(d);
  REQUIRE(d.findings.size() >= 2);
  CHECK(d.findings[0].effect == "sinusoid");
  CHECK(d.findings[0].reported);
  const auto& second = d.findings[1];
  CHECK(second.reported);
  const bool slowBias = second.effect == "random_walk" ||
                        (second.effect == "gauss_markov" && second.params.at("tau") >= 10.0);
  CHECK(slowBias);
  const auto imp = dg::improve(r, base, {dg::AddRequest::parse("found:gx")}, options());
  CHECK(imp.after.axis("gx").misfit <= 0.5 * imp.before.axis("gx").misfit);
}

// A line sweeping 2 -> 6 Hz (a chirp: no effect of the catalogue) was named gauss_markov, T 0.08 s
// (bench/blind_probe/diag59: 15/19 at 2x and 6x), and `--add found` wrote it although the misfit
// rose with it (0.357 -> 0.365, outside the band 62 % -> 85 %; on held-out records worse 10/12).
// A channel whose misfit and share outside both grow is now left as it was, with a note.
TEST_CASE("an added effect that raises the misfit is not written", "[diagnose][hidden]") {
  auto r = record("", 301);
  const double duration = double(kSamples) / kRate;
  double phase = 0.0;
  for (std::size_t k = 0; k < kSamples; ++k) {
    const double t = double(k) / kRate;
    phase += 2.0 * M_PI * (2.0 + 4.0 * t / duration) / kRate;
    r.gyro[0][k] += 0.1 * M_PI / 180.0 * std::sin(phase);  // 0.1 deg/s, ~2x the base's sd
  }
  const ErrorModelSpec base = errorModelFromString(kBase, "base.yaml");  // the true base
  const auto imp = dg::improve(r, base, {dg::AddRequest::parse("found:gx")}, options());
  const auto& before = imp.before.axis("gx");
  const auto& after = imp.after.axis("gx");
  print(before);
  print(after);
  for (const auto& n : imp.notes) std::cout << "  note: " << n << "\n";
  REQUIRE_FALSE(before.findings.empty());
  CHECK(before.findings.front().reported);  // something was named, so something was tried
  REQUIRE(imp.changes.size() == 1);
  const bool notes = std::any_of(imp.notes.begin(), imp.notes.end(), [](const std::string& n) {
    return n.find("gx: ") == 0 && n.find(" not added: the misfit rose with it") != std::string::npos;
  });
  CHECK(notes);
  CHECK(imp.changes[0].added.empty());
  CHECK(imp.model.gyro.x.size() == base.gyro.x.size());  // the file holds the model as given
  CHECK(after.misfit == Approx(before.misfit).epsilon(1e-12));
}

TEST_CASE("nothing hidden gives no reported finding", "[diagnose][null]") {
  for (std::uint64_t seed : {201, 202, 203}) {
    const auto r = record("", seed);
    const auto d = dg::diagnose(r, fitBase(r), options());
    std::cout << "null seed " << seed << ":\n";
    print(d.axis("gx"));
    for (const auto& f : d.axis("gx").findings) {
      INFO(f.effect << " score " << f.score);
      CHECK_FALSE(f.reported);
    }
    // A right model leaves nothing unexplained: the remaining chi2 is below its 0.999 quantile
    // (P = 0.1 % per channel if the chi2 law held exactly; three seeds).
    CHECK_FALSE(d.axis("gx").unexplained.has_value());
  }
}

TEST_CASE("the same seed gives identical diagnoses and threads do not matter", "[diagnose]") {
  const auto r = record("    - {type: random_walk, K: 0.0005 deg/s/sqrt(s)}\n", 102);
  const auto base = fitBase(r);
  auto o1 = options();
  o1.threads = 1;
  auto o2 = options();
  o2.threads = 2;
  // Realisation r is StreamKey (seed, r) whatever thread runs it: bit-identical output.
  CHECK(dg::toJson(dg::diagnose(r, base, o1)) == dg::toJson(dg::diagnose(r, base, o2)));
}

TEST_CASE("the improved model file loads and its JSON carries before and after", "[diagnose]") {
  const auto r = record("    - {type: warmup, amplitude: 0.1 deg/s, tau: 60 s}\n", 107);
  const auto imp = dg::improve(r, fitBase(r), {dg::AddRequest::parse("warmup")}, options());
  // The written model is an ordinary model file: it reads back as the improved spec (whose values
  // are as written) and names the added effect.
  const std::string text = sinsim::errormodels::errorModelYaml(imp.model);
  CHECK(errorModelFromString(text, "improved.yaml") == imp.model);
  const auto m = sinsim::errormodels::ImuErrorModel::fromString(text, "improved.yaml");
  bool hasWarmup = false;
  for (const auto& n : m.effectNames()) hasWarmup = hasWarmup || n.find("warmup") != std::string::npos;
  CHECK(hasWarmup);
  const auto j = dg::toJson(imp);
  for (const char* key : {"\"misfit_before\"", "\"misfit_after\"", "\"findings\"", "\"fails\"",
                          "\"evidence\"", "\"score\"", "\"drop\"", "\"size\""})
    CHECK(j.find(key) != std::string::npos);
  CHECK(imp.changes.at(0).misfitAfter < imp.changes.at(0).misfitBefore);
  const auto table = dg::summaryTable(imp);
  CHECK(table.find("warmup") != std::string::npos);
}

TEST_CASE("bad requests are refused with a clear message", "[diagnose]") {
  CHECK_THROWS_WITH(dg::AddRequest::parse("jitter"), Catch::Contains("can add: quantization"));
  CHECK_THROWS_WITH(dg::AddRequest::parse("ramp:gq"), Catch::Contains("--add ramp:gq: unknown channel \"gq\""));
  const auto r = record("", 201);
  auto o = options();
  o.realisations = 4;
  CHECK_THROWS_WITH(dg::diagnose(r, fitBase(r), o), Catch::Contains("at least 8"));
  o = options();
  o.nextThreshold = std::nan("");
  CHECK_THROWS_WITH(dg::diagnose(r, fitBase(r), o), Catch::Contains("--next-threshold"));
  // A temperature model on a record without temperature.
  const auto temp = errorModelFromString(
      "gyro:\n  x:\n    - {type: temperature, T0: 25 degC, coefficients: [0.01 deg/s/degC]}\n", "t.yaml");
  CHECK_THROWS_WITH(dg::diagnose(r, temp, options()), Catch::Contains("temperature"));
}

TEST_CASE("the value lattice is found exactly and not invented", "[diagnose]") {
  using sinsim::errormodels::latticeStep;
  std::vector<double> y, z;
  for (int k = 0; k < 5000; ++k) {
    const double v = std::sin(0.37 * k) * 3 + std::cos(1.1 * k);  // continuous values
    z.push_back(v);
    y.push_back(0.00333 * std::nearbyint(v / 0.00333) + 0.001);  // on a lattice with an offset
  }
  CHECK(latticeStep(y) == Approx(0.00333).epsilon(1e-9));
  CHECK(latticeStep(z) == 0.0);
}

// A record written with a fixed number of decimals sits on a value lattice too: gx's base
// (sd ~2e-3 rad/s) on a 0.5 rad/s offset written as %.7f is on a 1e-7 rad/s lattice, whose
// rounding adds q^2/12 ~ 1e-15 rad^2/s^2 -- ~1e-10 of the record's one-sample Allan variance,
// far below its own scatter (sqrt(3/N) = 0.4 %). No lattice quantization is proposed (before: a finding
// of score 40 on every such channel), the lattice is still found, and a real LSB of the same
// record's size (the ADIS16405's, above) still is.
TEST_CASE("a CSV's printing precision is no quantization", "[diagnose]") {
  for (std::uint64_t seed : {204, 205}) {
    auto r = record("", seed);
    for (double& v : r.gyro[0]) v = 1e-7 * std::nearbyint((0.5 + v) / 1e-7);
    REQUIRE(sinsim::errormodels::latticeStep(r.gyro[0]) == Approx(1e-7).epsilon(1e-3));
    const auto d = dg::diagnose(r, fitBase(r), options());
    for (const auto& f : d.axis("gx").findings) {
      INFO(f.effect << " score " << f.score);
      CHECK(f.params.count("lattice") == 0);  // the lattice-free QN candidate may stand, unreported
      CHECK_FALSE(f.reported);
    }
  }
}

// A base whose density is 10x the record's (a model written in the wrong unit) cannot be lowered
// by any effect: the table says the level the record shows, the square root of the fitted
// variance factor (0.1 within the band's few %), and names the units and densities.
TEST_CASE("a model 10x too high is said to be off in level", "[diagnose]") {
  const auto r = record("", 206);
  auto base = fitBase(r);
  const auto tooHigh = errorModelFromString(
      "gyro:\n  x:\n    - {type: ar, a: [-1.2, 0.4], sigma: 0.2 deg/s, rate: 100 Hz}\n", "high.yaml");
  const auto d = dg::diagnose(r, tooHigh, options());
  CHECK(std::sqrt(d.axis("gx").noiseScale) == Approx(0.1).epsilon(0.05));
  const auto table = dg::summaryTable(d);
  CHECK_THAT(table, Catch::Contains("gx level: the record's noise is x0.1"));
  CHECK_THAT(table, Catch::Contains("units and densities"));
  CHECK_THAT(dg::summaryTable(dg::diagnose(r, base, options())), !Catch::Contains("level:"));
  // Beside a reported finding the level is said too, and that the finding was sized at it (a
  // model overstating one term alone leaves the others short by the same factor).
  auto withFinding = d;
  dg::Finding f;
  f.effect = "gauss_markov";
  f.reported = true;
  withFinding.axes.front().findings.insert(withFinding.axes.front().findings.begin(), f);
  const auto both = dg::summaryTable(withFinding);
  CHECK_THAT(both, Catch::Contains("gx level: the record's noise is x0.1") && Catch::Contains("check the base first"));
  CHECK_THAT(table, !Catch::Contains("check the base first"));
}

// A record of a white gyro whose density is 1.2x the model's: 1.44x in Allan variance at every
// tau, far outside the bands of 60 000 samples (chi2 of the model as given beyond its 0.999
// quantile), a level factor only once s is fitted (the fitted s within a few % of 1.44). The table
// says so instead of "no effect above threshold"; the model at its own density fits.
TEST_CASE("a record that differs from its model in level alone is said to", "[diagnose]") {
  const auto model = errorModelFromString("gyro:\n  x: [{type: white, density: 0.5 deg/sqrt(h)}]\n", "w.yaml");
  const auto louder = errorModelFromString("gyro:\n  x: [{type: white, density: 0.6 deg/sqrt(h)}]\n", "w12.yaml");
  auto o = options();
  o.channels = {"gx"};
  const auto r = dg::simulateRecord(louder, 100.0, 60000, 71, 0, {0, 0, 0, 0, 0, 0});
  const auto d = dg::diagnose(r, model, o);
  const auto& a = d.axis("gx");
  REQUIRE_FALSE(a.fits());
  CHECK(a.chi2 > sinsim::errormodels::chiSquareQuantile(0.999, double(a.chi2Points)));
  CHECK(a.noiseScale == Approx(1.44).epsilon(0.05));
  CHECK_THAT(dg::summaryTable(d), Catch::Contains("level only (x1.2"));
  CHECK_THAT(dg::summaryTable(dg::diagnose(r, louder, o)), !Catch::Contains("level only"));
}

// The diagnosis counts an effect as present exactly when the simulator runs it: `enabled: no`,
// `false` and `off` switch it off for both (the reader's side is in test_model_spec). A ramp on gx
// listed after the base keeps the base's random streams (they are keyed by list position), so a
// model with the ramp disabled must give the diagnosis of the model without it, bit for bit: the
// same realisations (simulator) and the same candidates, the ramp among them (diagnosis).
TEST_CASE("a disabled effect is absent for the diagnosis, as for the simulator", "[diagnose]") {
  const auto r = record("    - {type: ramp, slope: 900 deg/h^2}\n", 113);
  auto o = options();
  o.realisations = 8;
  const auto without = errorModelFromString(kBase, "m.yaml");
  const std::string absent = dg::toJson(dg::diagnose(r, without, o));
  CHECK(absent.find("\"effect\": \"ramp\"") != std::string::npos);
  for (const char* off : {"no", "false", "off"}) {
    INFO("enabled: " << off);
    const auto disabled = errorModelFromString(
        kBase + "    - {type: ramp, slope: 900 deg/h^2, enabled: " + off + "}\n", "m.yaml");
    CHECK(dg::toJson(dg::diagnose(r, disabled, o)) == absent);
  }
  // Enabled, the ramp is in the model: it is taken out of record and model (model_drift.hpp), the
  // record's ramp is the model's, and no ramp is reported.
  const auto on = errorModelFromString(kBase + "    - {type: ramp, slope: 900 deg/h^2, enabled: yes}\n", "m.yaml");
  const auto gx = dg::diagnose(r, on, o).axis("gx");
  CHECK(gx.modelDrift == Approx(900.0 * (M_PI / 180.0) / 3600.0 / 3600.0).epsilon(1e-9));
  for (const auto& f : gx.findings) CHECK(!(f.effect == "ramp" && f.reported));
}

// The user's pipeline on a record whose values sit on an output register's lattice: `fit` then
// `diagnose` of the same record. Each sample rounded is white noise to the Allan variance, so no
// composite fit selects a quantization term for it, while the diagnosis reads the lattice off the
// record and named `quantization` against the fitted model on 5 of the 6 channels of ADIS16405 run
// 2's window and on ~1 in 6 clean channels of the challenge generators. The fit now writes the
// lattice it sees as a rate LSB, its white noise moved out of the white term: the truth's density
// back within 3 sigma (before: the rounding's 5 % of the variance in it, ~2.6 % high).
TEST_CASE("fit writes a record's value lattice and diagnose of the same record names no quantization",
          "[diagnose][identify]") {
  const double lsb = 1.0;  // deg/s, 0.8 of the white's sd per sample: rounding adds 5.3 % of the variance
  const std::string truth =
      "gyro:\n"
      "  x:\n"
      "    - {type: white, density: 7.5 deg/sqrt(h)}\n"  // sd 7.5 / 60 * sqrt(100) = 1.25 deg/s
      "    - {type: quantization, lsb: " + std::to_string(lsb) + " deg/s}\n";
  for (std::uint64_t seed : {131, 132, 133})
    for (auto kind : {sinsim::errormodels::IdentifyKind::Auto, sinsim::errormodels::IdentifyKind::Gm}) {
      INFO("seed " << seed << ", kind " << int(kind));
      const auto r = dg::simulateRecord(errorModelFromString(truth, "truth.yaml"), kRate, kSamples, seed, 0,
                                        {0, 0, 0, 0, 0, 0});
      sinsim::errormodels::IdentifyOptions io;
      io.axes = {"gx"};
      io.kind = kind;
      const auto id = sinsim::errormodels::identify(r, io);
      const auto& w = id.axis("gx").written;
      CHECK(w.roundedRateLsb == Approx(lsb * M_PI / 180.0).epsilon(1e-6));
      REQUIRE(w.latent);
      if (kind == sinsim::errormodels::IdentifyKind::Auto) CHECK(w.latent->terms.name() == "white");
      const double N = 7.5 * (M_PI / 180.0) / 60.0;  // rad/sqrt(s)
      CHECK(std::fabs(w.latent->model.white - N) <= 3.0 * w.latent->parameter("white").stdError);
      auto spec = sinsim::errormodels::asWritten(id.modelSpec());
      spec.source = "fitted.yaml";
      const auto gx = dg::diagnose(r, spec, options()).axis("gx");
      print(gx);
      for (const auto& f : gx.findings) CHECK(!(f.effect == "quantization" && f.reported));
    }
}

TEST_CASE("diagnose: an effect added to a channel the diagnosis leaves out is refused, naming the channels diagnosed", "[diagnose]") {
  // Before, `--channels gx --add ramp:az` wrote an "improved" model with nothing added, exit 0.
  const auto r = record("", 7);
  const auto base = errorModelFromString(kBase, "base.yaml");
  try {
    (void)dg::improve(r, base, {dg::AddRequest::parse("ramp:az")}, options());
    FAIL("expected an InputError");
  } catch (const sinsim::InputError& e) {
    CHECK(std::string(e.what()).find("--add ramp:az: az is not among the channels diagnosed (gx)") != std::string::npos);
  }
}
