// The sentence that states a comparison's answer (sim/mc_headlines.hpp), from numbers given here.
#include <catch2/catch.hpp>

#include <utility>

#include "sim/mc_headlines.hpp"

using sinsim::sim::McPairedHeadline;

TEST_CASE("the paired comparison in one sentence") {
  McPairedHeadline p;
  p.a = "AR";
  p.b = "GM";
  p.t = 600.0;
  p.runs = 100;
  p.meanA = 15.2;
  p.meanB = 16.72;  // 10 % more
  p.pT = 1.2e-12;
  CHECK(p.sentence() ==
        "GM predicts 10 % more horizontal drift than AR at 10 min (mean 16.7 m vs 15.2 m, 100 "
        "paired runs, paired t-test p = 1e-12).");
  // The larger one is named first whichever side it is on.
  std::swap(p.meanA, p.meanB);
  CHECK(p.sentence().rfind("AR predicts 10 % more horizontal drift than GM at 10 min", 0) == 0);
  // Twice or more: a ratio.
  p.meanA = 49980.0;
  p.meanB = 1000.0;
  CHECK(p.sentence() ==
        "AR predicts 50 times the horizontal drift of GM at 10 min (mean 50.0 km vs 1.00 km, 100 "
        "paired runs, paired t-test p = 1e-12).");
  // Not significant at 5 %: said so, with the numbers.
  p.meanA = 15.2;
  p.meanB = 15.3;
  p.pT = 0.41;
  CHECK(p.sentence() ==
        "No significant difference in horizontal drift between GM and AR at 10 min (mean 15.3 m "
        "vs 15.2 m, 100 paired runs, paired t-test p = 0.41).");
}
