// --add found on a Gauss-Markov model fitted to the real ADIS16405 run 1 (../shared/data/adis16405,
// 100 Hz, 10 000 s; data: SMAC-Group imudata, University of Calgary, CC BY-NC-SA 4.0) writes an
// improved model (issue 10: it failed after the whole diagnosis with "accel.x[0].sigma: must be
// positive, got 0 mg", naming a file that did not exist). The path of the CLI: the fit writes its
// model file, the diagnosis reads it once, improves the spec, and the one writer writes it.
#include <catch2/catch.hpp>

#include <fstream>
#include <string>

#include "../test_support.hpp"
#include "errormodels/diagnose/diagnose.hpp"
#include "errormodels/identify.hpp"
#include "errormodels/imu_model.hpp"
#include "errormodels/model_io.hpp"

using namespace sinsim::errormodels;
namespace dg = sinsim::errormodels::diagnose;

TEST_CASE("ADIS16405 run 1: --add found on a fitted GM model writes an improved model",
          "[diagnose][adis16405]") {
  const std::string data = std::string(SINSIM_SHARED_DIR) + "/data/adis16405/run1.csv.gz";
  if (!std::ifstream(data)) {
    WARN("ADIS16405 data not found at " << data << ": skipped");
    return;
  }
  RecordOptions ro;
  ro.rate_hz = 100.0;
  ro.gyro_unit = "deg/s";
  ro.accel_unit = "g";
  const Record record = loadRecord(data, ro);
  // The channel of the report (ax) and the gyro whose fit is the least consistent (gz).
  IdentifyOptions io;
  io.kind = IdentifyKind::Gm;
  io.axes = {"gz", "ax"};
  const auto dir = sinsim::test::freshTempDir("sinsim_diagnose_adis_gm");
  const std::string gm = (dir / "gm.yaml").string(), improved = (dir / "gm.improved.yaml").string();
  identify(record, io).writeModel(gm);

  dg::DiagnoseOptions o;
  o.channels = {"gz", "ax"};
  o.realisations = 16;
  const auto imp = dg::improve(record, loadErrorModel(gm), {dg::AddRequest::parse("found")}, o);
  std::size_t added = 0;
  for (const auto& ch : imp.changes) added += ch.added.size();
  CHECK(added > 0);  // the record has what a GM lacks (its lattice at least)
  writeErrorModel(improved, imp.model);
  // The written file reads back as the improved spec and is a valid model.
  const auto back = loadErrorModel(improved);
  CHECK(back == imp.model);
  CHECK_NOTHROW(ImuErrorModel::fromSpec(back, improved));
}
