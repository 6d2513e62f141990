// The sentence that states a comparison's answer (sim/mc_headlines.hpp), from numbers given here.
#include <catch2/catch.hpp>

#include <cmath>
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

TEST_CASE("the paired comparison's words follow the ratio as printed, without exponents") {
  McPairedHeadline p;
  p.a = "x1";
  p.b = "x2";
  p.t = 120.0;
  p.runs = 200;
  p.pT = 1e-300 * 1e-20;  // a denormal p: below what is printed
  // helper-21: twice the noise, exactly twice the drift up to rounding: "2 times" either side of 2.
  p.meanA = 1.0;
  p.meanB = 1.9999999988;
  CHECK(p.sentence() == "x2 predicts 2 times the horizontal drift of x1 at 2 min (mean 2.00 m vs "
                        "1.00 m, 200 paired runs, paired t-test p < 1e-300).");
  p.meanB = 2.000000004;
  CHECK(p.sentence().rfind("x2 predicts 2 times the horizontal drift of x1", 0) == 0);
  p.meanB = 1.94;  // printed 1.9: a percentage
  CHECK(p.sentence().rfind("x2 predicts 94 % more horizontal drift than x1", 0) == 0);
  p.meanB = 2234.0;
  CHECK(p.sentence().rfind("x2 predicts 2234 times the horizontal drift of x1", 0) == 0);
  // One pair: no p-value, one run.
  p.runs = 1;
  p.pT = NAN;
  CHECK(p.sentence() == "No significant difference in horizontal drift between x2 and x1 at 2 min "
                        "(mean 2.23 km vs 1.00 m, 1 paired run, paired t-test p not defined).");
}
