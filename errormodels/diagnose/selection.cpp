// Forward selection of the candidates by score (selection.hpp).
#include "errormodels/diagnose/selection.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "errormodels/diagnose/significance.hpp"

namespace sinsim::errormodels::diagnose::detail {

namespace {

/// Each candidate's last trial fit (with the accepted ones) and its score.
struct Trials {
  std::vector<double> score, dchi;
  std::vector<AllanSolution> sol;
};

/// Scores every candidate whose effect is not accepted yet against the current fit: the larger of
/// sqrt(chi2 reduction) and its own tests, capped. Returns the best, or -1 when none is left.
std::ptrdiff_t scoreRound(const ChannelWork& w, Trials& t) {
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
    t.sol[i] = solveAllan(w.prob, trial, start);
    t.dchi[i] = w.sol.chi2 - t.sol[i].chi2;
    double z = std::max(std::sqrt(std::max(0.0, t.dchi[i])), w.cands[i].zSpecial);
    if (w.cands[i].zConditional) z = std::max(z, w.cands[i].zConditional(currentAvar));
    t.score[i] = std::min(kMaxScore, z);
    if (best < 0 || t.score[i] > t.score[std::size_t(best)] ||
        (t.score[i] == t.score[std::size_t(best)] && t.dchi[i] > t.dchi[std::size_t(best)]))
      best = std::ptrdiff_t(i);
  }
  return best;
}

/// One finding per effect not accepted (its best-scoring variant), by score.
std::vector<Finding> otherFindings(const ChannelWork& w, const Trials& t) {
  std::vector<Finding> rest;
  std::set<std::string> taken;
  for (auto i : w.accepted) taken.insert(w.cands[i].effect);
  for (std::size_t i = 0; i < w.cands.size(); ++i) {
    if (taken.count(w.cands[i].effect)) continue;
    Finding f;
    f.effect = w.cands[i].effect;
    f.evidence = w.cands[i].evidence;
    f.score = t.score[i];
    w.cands[i].describe(t.sol[i].theta.empty() ? 0.0 : t.sol[i].theta.back(), f);
    auto it = std::find_if(rest.begin(), rest.end(), [&](const Finding& g) { return g.effect == f.effect; });
    if (it == rest.end()) rest.push_back(f);
    else if (f.score > it->score) *it = f;
  }
  std::stable_sort(rest.begin(), rest.end(), [](const Finding& a, const Finding& b) { return a.score > b.score; });
  return rest;
}

}  // namespace

void selectFindings(ChannelWork& w, double threshold) {
  AxisDiagnosis& d = w.d;
  w.sol = solveAllan(w.prob, {});
  Trials t;
  t.score.assign(w.cands.size(), 0.0);
  t.dchi.assign(w.cands.size(), 0.0);
  t.sol.resize(w.cands.size());
  for (;;) {
    const std::ptrdiff_t best = scoreRound(w, t);
    if (best < 0 || t.score[std::size_t(best)] < threshold) break;
    Finding f;
    f.effect = w.cands[std::size_t(best)].effect;
    f.score = t.score[std::size_t(best)];
    f.reported = true;
    w.accepted.push_back(std::size_t(best));
    w.sol = t.sol[std::size_t(best)];
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
  for (auto& f : otherFindings(w, t)) d.findings.push_back(f);
}

}  // namespace sinsim::errormodels::diagnose::detail
