// The detector registry and the candidates of one channel (detector.hpp).
#include "errormodels/diagnose/detector.hpp"

#include <algorithm>
#include <cmath>

#include "errormodels/diagnose/low_frequency.hpp"
#include "errormodels/diagnose/significance.hpp"

namespace sinsim::errormodels::diagnose::detail {

const std::vector<DetectorType>& detectorTypes() {
  static const std::vector<DetectorType> types = {
#define SINSIM_DETECTOR(effect, repeatable, summary) {#effect, repeatable, summary, &detect_##effect},
#include "errormodels/diagnose/detectors.def"
#undef SINSIM_DETECTOR
  };
  return types;
}

// For white noise Var c = sigma^2 / x'x and the least-squares trend's variance is sigma^2 / t't
// (t't = dt^2 N (N^2 - 1) / 12), hence Var c = V_trend t't / x'x. For red noise this overstates
// Var c when x has no more of its variance at the lowest frequencies than a line: computed
// exactly (x' Sigma x / (x'x)^2 against this) for a walk and a GM of T/30, 0.51-0.95 for settling
// curves of time constant T/10-T/4, 0.83 for a step, at most 1.03 for a half-cosine (the shape
// with the least high-frequency content), but 0.29 / 0.065 at T/20 / T/100 (a walk): a short
// settling varies where a red noise has little power. So the accepted noises' share (known in
// closed form, TrendScatter::knownAvar) is the smaller of this and their variance on x's cosines
// (coefficientVarianceOf: exact for a walk, 1.22x for white noise); the realisations' share keeps
// the line's ratio. The line's V_trend includes the Gaussian noise the record without x's fit
// still shows (ModelNow::trendVarWith), so a walk the model lacks does not pass for x.
//
// Least squares weighs every frequency of x alike, so against a red noise it is not the best test
// of a shape: a settling of T/20 on a walk is seen ~3x better by generalised least squares, which
// weighs the cosines where the noise is small (glsTestOf). A shape other than the plain line is
// therefore tested by GLS on the cosines under the whole model: the base at its level
// (TrendScatter::baseAvar) and the Gaussian noise the record without x still shows
// (TrendScatter::fittedAvar) as estimated, the accepted noises as known. The fitted noise counts
// as estimated: counted as known, a warm-up fitted to a ramp made its own misfit into a walk whose
// variance escaped the realisations' dof, and won over the ramp. The plain line keeps least
// squares: its information sits in the first cosine, where GLS gains little (6/5 in variance on a
// walk), and its share of
// the short-correlated noises above is exact rather than converted from their Allan variance.
namespace {

/// regressorTestGivenModel; `line`: the shape is the plain least-squares line (the ramp with no
/// signal taken out), whose scatter under the accepted noises whose autocovariance dies out within
/// the Allan grid is exact (TrendScatter::exactLine) instead of on the high side.
std::function<double(const ModelNow&)> regressorTest(const DetectorContext& ctx, const std::vector<double>& shape,
                                                     double trials, const std::vector<std::vector<double>>& beside,
                                                     bool line) {
  const bool apart = !ctx.taken.empty() || !beside.empty();
  const std::vector<double> x = apart ? ctx.apart(shape, beside) : shape;
  const std::vector<double> yBeside = beside.empty() ? std::vector<double>{} : ctx.apart(ctx.y, beside);
  const std::vector<double>& y = beside.empty() ? ctx.y : yBeside;
  double xm = 0, ym = 0;
  for (std::size_t k = 0; k < ctx.N; ++k) xm += x[k] / double(ctx.N), ym += y[k] / double(ctx.N);
  double xx = 0, xy = 0;
  for (std::size_t k = 0; k < ctx.N; ++k) xx += (x[k] - xm) * (x[k] - xm), xy += (x[k] - xm) * (y[k] - ym);
  if (!(xx > 0)) return {};
  const double c = xy / xx, n = double(ctx.N);
  const double tt = ctx.dt * ctx.dt * n * (n * n - 1) / 12;
  std::vector<double> rest(ctx.N);
  for (std::size_t k = 0; k < ctx.N; ++k) rest[k] = y[k] - c * (x[k] - xm);
  line = line && !apart;
  return [c, trials, line, ratio = tt / xx, avar = allanVariance(rest, ctx.setup), spectrum = cosineSpectrum(x),
          ySpectrum = line ? CosineSpectrum{} : beside.empty() ? ctx.ySpectrum : cosineSpectrum(y), tau = ctx.tau, T = ctx.T,
          dt = ctx.dt](const ModelNow& m) {
    const TrendScatter s = m.trendVarWith ? m.trendVarWith(avar) : TrendScatter{m.trendVar, m.trendDof, 0.0, {}, 0.0, 0.0, {}, {}, {}};
    // The accepted noises' share: the smaller of two high-side bounds, or for the line the exact
    // share of the short-correlated ones (Candidate::acovSpan) and the bounds for the rest.
    const double bounded = line ? s.restKnown : s.known * ratio;
    const std::vector<double>& boundedAvar = line ? s.restAvar : s.knownAvar;
    double known = bounded;
    if (known > 0 && !boundedAvar.empty()) known = std::min(known, coefficientVarianceOf(spectrum, boundedAvar, tau, T, dt));
    if (line) known += s.exactLine;
    const double realised = s.realised * ratio, var = realised + known;
    const double dof = satterthwaiteDof(realised, s.realisedDof, known);
    if (!(var > 0) || !(dof > 1)) return 0.0;
    double t = std::fabs(c) / std::sqrt(var), nu = dof;
    if (!line && !s.baseAvar.empty()) {
      std::vector<double> estimated = s.baseAvar, accepted = s.knownAvar;
      for (std::size_t k = 0; k < s.fittedAvar.size() && k < accepted.size() && k < estimated.size(); ++k)
        estimated[k] += s.fittedAvar[k], accepted[k] = std::max(0.0, accepted[k] - s.fittedAvar[k]);
      const GlsTest g = glsTestOf(spectrum, ySpectrum, estimated, accepted, s.realisedDof, tau, T, dt);
      t = g.t, nu = g.dof;
      if (!(nu > 1)) return 0.0;
    }
    const double z = zFromStudentT(t, nu);
    return trials > 1 ? zFromTwoSidedP(std::min(1.0, trials * std::erfc(z / std::sqrt(2.0)))) : z;
  };
}

}  // namespace

std::function<double(const ModelNow&)> regressorTestGivenModel(const DetectorContext& ctx,
                                                               const std::vector<double>& shape, double trials,
                                                               const std::vector<std::vector<double>>& beside) {
  return regressorTest(ctx, shape, trials, beside, false);
}

std::function<double(const ModelNow&)> trendTestGivenModel(const DetectorContext& ctx, const std::vector<double>& line) {
  return regressorTest(ctx, line, 1, {}, true);
}

namespace {

/// The columns [1, vs...] (N rows) as a matrix.
Eigen::MatrixXd withConstant(std::size_t N, const std::vector<std::vector<double>>& vs) {
  Eigen::MatrixXd A(Eigen::Index(N), Eigen::Index(vs.size() + 1));
  A.col(0).setOnes();
  for (std::size_t j = 0; j < vs.size(); ++j)
    A.col(Eigen::Index(j + 1)) = Eigen::Map<const Eigen::VectorXd>(vs[j].data(), Eigen::Index(N));
  return A;
}

/// An orthonormal basis of the column span of A (rank-revealing QR: nearly collinear columns
/// count once).
Eigen::MatrixXd orthonormalBasis(const Eigen::MatrixXd& A) {
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
  return qr.householderQ() * Eigen::MatrixXd::Identity(A.rows(), qr.rank());
}

}  // namespace

std::vector<double> DetectorContext::apart(const std::vector<double>& x,
                                           const std::vector<std::vector<double>>& beside) const {
  const Eigen::Map<const Eigen::VectorXd> xv(x.data(), Eigen::Index(N));
  std::vector<double> out(N);
  Eigen::Map<Eigen::VectorXd> o(out.data(), Eigen::Index(N));
  if (beside.empty() && takenBasis.size() > 0) {
    o = xv - takenBasis * (takenBasis.transpose() * xv);
    return out;
  }
  Eigen::MatrixXd A = withConstant(N, beside);
  if (takenBasis.size() > 0) {
    Eigen::MatrixXd B(A.rows(), A.cols() + takenBasis.cols());
    B << A, takenBasis;
    A = std::move(B);
  }
  Eigen::VectorXd beta;
  leastSquares(A, xv, beta);
  o = xv - A * beta;
  return out;
}

bool DetectorContext::spanned(const std::vector<double>& x) const {
  if (taken.empty()) return false;
  double m = 0;
  for (double v : x) m += v / double(N);
  double ss = 0, rr = 0;
  for (double v : x) ss += (v - m) * (v - m);
  for (double v : apart(x)) rr += v * v;
  return !(rr > 1e-9 * ss);
}

std::vector<Candidate> buildCandidates(const Record& record, int channel, const std::vector<double>& y,
                                       double lattice, const std::vector<double>& tau, const Setup& setup,
                                       const std::vector<std::string>& modelEffects,
                                       const std::vector<std::vector<double>>& taken,
                                       const std::vector<double>& roundingAvar,
                                       const std::vector<Line>& linesTaken,
                                       const std::vector<double>& steps) {
  const std::size_t N = y.size();
  const double dt = 1.0 / record.rate_hz;
  double mean = 0;
  for (double v : y) mean += v;
  mean /= double(N);
  double var = 0;
  for (double v : y) var += (v - mean) * (v - mean);
  var /= double(N);
  DetectorContext ctx{record, channel, y, N, dt, double(N) * dt, tau, setup, unitsFor(channel),
                      mean, var, lattice, blockMeans(y, dt, 2000), modelEffects,
                      isGyro(channel) ? Dimension::angularRate() : Dimension::acceleration(), taken, {}, {}, {}, {}, {},
                      cosineSpectrum(y)};
  for (const auto& x : taken) ctx.takenBlocks.push_back(blockMeans(x, dt, 2000).m);
  if (!taken.empty()) ctx.takenBasis = orthonormalBasis(withConstant(N, taken));
  ctx.roundingAvar = roundingAvar;
  ctx.linesTaken = linesTaken;
  ctx.steps = steps;
  std::vector<Candidate> out;
  for (const auto& d : detectorTypes()) {
    if (!d.repeatable && std::find(modelEffects.begin(), modelEffects.end(), d.effect) != modelEffects.end())
      continue;
    for (auto& c : d.detect(ctx)) out.push_back(std::move(c));
  }
  return out;
}

}  // namespace sinsim::errormodels::diagnose::detail
