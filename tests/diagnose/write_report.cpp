// Writes a diagnosis report of a small synthetic case (AR(2) base fitted to a record with a
// hidden random walk, the walk added) for the headless-Chromium render check.
#include <iostream>

#include "errormodels/diagnose/diagnose.hpp"
#include "errormodels/identify.hpp"
#include "errormodels/model_io.hpp"
#include "sim/diagnose_report.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: write_diagnose_report OUT.html\n";
    return 2;
  }
  namespace dg = sinsim::errormodels::diagnose;
  const std::string truth =
      "gyro:\n  x:\n    - {type: ar, a: [-1.2, 0.4], sigma: 0.02 deg/s, rate: 100 Hz}\n"
      "    - {type: random_walk, K: 0.0005 deg/s/sqrt(s)}\n";
  const auto r = dg::simulateRecord(sinsim::errormodels::errorModelFromString(truth, "truth.yaml"), 100, 100000, 5, 0, {0, 0, 0, 0, 0, 0});
  sinsim::errormodels::IdentifyOptions io;
  io.axes = {"gx"};
  io.kind = sinsim::errormodels::IdentifyKind::Ar;
  io.order = 2;
  auto base = sinsim::errormodels::identify(r, io).modelSpec();
  base.source = "fitted.yaml";
  dg::DiagnoseOptions o;
  o.channels = {"gx"};
  o.realisations = 16;
  const auto imp = dg::improve(r, base, {dg::AddRequest::parse("random_walk")}, o);
  sinsim::writeDiagnoseReport(argv[1], imp.before, &imp);
  return 0;
}
