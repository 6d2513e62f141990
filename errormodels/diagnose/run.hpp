// The working state of one diagnosis, per channel, that improve() continues from: the Allan
// problem, the candidates and the accepted ones (not a public API).
#pragma once

#include <vector>

#include "errormodels/diagnose/allan_chi2.hpp"
#include "errormodels/diagnose/candidate.hpp"

namespace sinsim::errormodels::diagnose::detail {

struct ChannelWork {
  std::vector<std::size_t> factors;  // averaging factors of the tau grid
  int channel = 0;
  AxisDiagnosis d;
  AllanProblem prob;
  std::vector<Candidate> cands;
  std::vector<std::size_t> accepted;  // indices into cands, in acceptance order
  AllanSolution sol;                  // the joint fit of the accepted ones
};

struct Run {
  Diagnosis d;
  std::vector<ChannelWork> work;
};

/// The diagnosis with its working state (diagnose() keeps only run.d).
Run diagnoseRun(const Record& record, const ErrorModelSpec& model, const DiagnoseOptions& o);

}  // namespace sinsim::errormodels::diagnose::detail
