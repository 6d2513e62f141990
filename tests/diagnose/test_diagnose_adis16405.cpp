// --add found on a Gauss-Markov model fitted to the real ADIS16405 run 1 (../shared/data/adis16405,
// 100 Hz, 10 000 s; data: SMAC-Group imudata, University of Calgary, CC BY-NC-SA 4.0) writes an
// improved model (issue 10: it failed after the whole diagnosis with "accel.x[0].sigma: must be
// positive, got 0 mg", naming a file that did not exist). The path of the CLI: the fit writes its
// model file, the diagnosis reads it once, improves the spec, and the one writer writes it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "../test_support.hpp"
#include "errormodels/diagnose/diagnose.hpp"
#include "../adis16405_records.hpp"
#include "errormodels/identify.hpp"
#include "errormodels/imu_model.hpp"
#include "errormodels/model_io.hpp"

using namespace sinsim::errormodels;
namespace dg = sinsim::errormodels::diagnose;

TEST_CASE("ADIS16405 run 1: --add found on a fitted GM model writes an improved model, each effect as shown",
          "[diagnose][adis16405]") {
  const std::string data = std::string(SINSIM_SHARED_DIR) + "/data/adis16405/run1.csv.gz";
  if (!std::ifstream(data)) {
    WARN("ADIS16405 data not found at " << data << ": skipped");
    return;
  }
  const RecordOptions ro = sinsim::test::adisOptions();
  const Record record = loadRecord(data, ro);
  // Two channels whose findings lower the misfit (gy, ay) and one whose findings raise it (ax: a
  // Gauss-Markov of tau 0.11 s, a random walk and outliers took its misfit 0.072 -> 0.092 and the
  // tau outside the band 45 % -> 76 %, and were written all the same until the fifty-ninth session).
  IdentifyOptions io;
  io.kind = IdentifyKind::Gm;
  io.axes = {"gy", "ay", "ax"};
  const auto dir = sinsim::test::freshTempDir("sinsim_diagnose_adis_gm");
  const std::string gm = (dir / "gm.yaml").string(), improved = (dir / "gm.improved.yaml").string();
  identify(record, io).writeModel(gm);

  dg::DiagnoseOptions o;
  o.channels = {"gy", "ay", "ax"};
  o.realisations = 16;
  const auto imp = dg::improve(record, loadErrorModel(gm), {dg::AddRequest::parse("found")}, o);
  std::size_t added = 0, reverted = 0;
  for (const auto& ch : imp.changes) {
    INFO(ch.channel << " misfit " << ch.misfitBefore << " -> " << ch.misfitAfter << ", outside "
                    << ch.fractionOutsideBefore << " -> " << ch.fractionOutsideAfter);
    // Never written worse on both measures.
    CHECK_FALSE((ch.misfitAfter > ch.misfitBefore && ch.fractionOutsideAfter >= ch.fractionOutsideBefore));
    added += ch.added.size();
    const bool noted = std::any_of(imp.notes.begin(), imp.notes.end(), [&](const std::string& n) {
      return n.rfind(ch.channel + ": ", 0) == 0 && n.find("not added: the misfit rose with it") != std::string::npos;
    });
    if (noted) {
      ++reverted;
      CHECK(ch.added.empty());
      CHECK(ch.misfitAfter == ch.misfitBefore);
    }
  }
  CHECK(added > 0);     // the record has what a GM lacks (its lattice at least)
  CHECK(reverted > 0);  // and what the catalogue's effects, as sized, fit worse
  // What is written is what was shown: each reported effect is added as the variant reported (its
  // correlation time, its line's frequency), only its size refitted beside the others. Before,
  // --add sized every variant of the effect and kept the one of least Allan chi2: on this record
  // ax showed a Gauss-Markov of tau 0.11 s and wrote one of tau 0.32 s.
  for (const auto& ch : imp.changes) {
    if (ch.added.empty()) continue;
    for (const auto& f : imp.before.axis(ch.channel).findings) {
      if (!f.reported) continue;
      for (const char* shape : {"tau", "frequency"}) {
        const auto* shown = f.spec.find(shape);
        if (!shown) continue;
        bool written = false;
        for (const auto& a : ch.added)
          if (a.type == f.spec.type && a.find(shape))
            written = written || std::fabs(a.find(shape)->si() - shown->si()) <= 1e-9 * std::fabs(shown->si());
        INFO(ch.channel << " " << f.effect << " " << shape << " shown " << shown->si());
        CHECK(written);
      }
    }
  }
  writeErrorModel(improved, imp.model);
  // The written file reads back as the improved spec and is a valid model.
  const auto back = loadErrorModel(improved);
  CHECK(back == imp.model);
  CHECK_NOTHROW(ImuErrorModel::fromSpec(back, improved));
}

// A warm-up on a real record: ADIS16405 run 2, 1000 s after its first 10 min, az with a settling
// of -56 mg (tau 44.7 s, 10x the channel's ADEV where the settling's is largest: the run-2
// injection i012 of bench/diagnose_challenge/adis_inject.py) put back on the 3.33 mg lattice,
// against the model `fit --kind gm` writes for the plain window (as the benchmark does). The
// level-step test cuts the settling into ~16 steps beside the sensor's own blips, and every
// candidate was credited only with what it explains on the record without those steps, where the
// settling is gone: the warm-up gained nothing (score 0) and a Gauss-Markov and a flicker took its
// excess. A signal whose removal takes most of the steps out is now credited on the record
// without the steps it leaves (selection.cpp, markJumps). Asserted: the warm-up is reported, its
// tau within 25 %, and it is the first finding beside the lattice and the stand's line.
TEST_CASE("ADIS16405 run 2: a warm-up cut into level steps is still found", "[diagnose][adis16405]") {
  const std::string data = std::string(SINSIM_SHARED_DIR) + "/data/adis16405/run2.csv.gz";
  if (!std::ifstream(data)) {
    WARN("ADIS16405 data not found at " << data << ": skipped");
    return;
  }
  const RecordOptions ro = sinsim::test::adisOptions(600.0, 1000.0);
  Record record = loadRecord(data, ro);
  IdentifyOptions io;
  io.kind = IdentifyKind::Gm;
  const auto dir = sinsim::test::freshTempDir("sinsim_diagnose_adis_warmup");
  const std::string gm = (dir / "plain-gm.yaml").string();
  identify(record, io).writeModel(gm);
  const double g0 = 9.80665, q = 0.00333 * g0, amplitude = -0.05604 * g0, tau = 44.697;
  auto& z = record.accel[2];
  for (std::size_t k = 0; k < z.size(); ++k)
    z[k] = q * std::round((z[k] + amplitude * std::exp(-double(k + 1) / 100.0 / tau)) / q);
  dg::DiagnoseOptions o;
  o.channels = {"az"};
  o.realisations = 16;
  const auto d = dg::diagnose(record, loadErrorModel(gm), o).axis("az");
  std::string reported;
  double found = 0;
  for (const auto& f : d.findings)
    if (f.reported) {
      reported += f.effect + " (" + std::to_string(f.score) + ") ";
      if (f.effect == "warmup") found = f.params.at("tau");
    }
  INFO("reported: " << reported);
  CHECK(found == Approx(tau).epsilon(0.25));
  // Before the selection's backward step a Gauss-Markov of tau 20 s was taken first (its Allan
  // hump fitted the settling's before the settling itself was tried) and stayed reported after
  // the warm-up took its excess, with sigma 0: the first finding the plain window does not have
  // (beside its lattice and the stand's line) was a GM no one injected. Now every reported noise
  // has a size, and the first finding beside the lattice and the line is the warm-up.
  std::string first;
  for (const auto& f : d.findings) {
    if (!f.reported) continue;
    for (const char* size : {"sigma", "B", "K", "density"})
      if (f.params.count(size)) CHECK(f.params.at(size) > 0);
    if (first.empty() && f.effect != "quantization" && f.effect != "sinusoid") first = f.effect;
  }
  CHECK(first == "warmup");
}
