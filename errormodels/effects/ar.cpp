// `ar`: autoregressive process of order p, in the MATLAB arburg convention of the seed paper:
//   A(z) = 1 + a1 z^-1 + ... + ap z^-p,   y[n] = -a1 y[n-1] - ... - ap y[n-p] + sigma_e w[n]
//   a: [-1.0327, -0.34341, 0.037895, 0.19732, 0.14724]   (a1..ap; arburg's output without its 1)
//   sigma: 0.01 deg/s          driving-noise standard deviation sigma_e (a standard deviation,
//                              NOT arburg's variance e: give sqrt(e))
//   or output_sigma: 0.1 deg/s stationary standard deviation of y; sigma_e = output_sigma / sqrt(G),
//                              G = r(0)/sigma_e² the variance gain of 1/A(z) (ar_model.hpp)
//   rate: 1 kHz                the sample rate the coefficients hold at (required: a discrete
//                              model means nothing without it)
//
// Generated at its own rate, each sample held over 1/rate and integrated into the IMU intervals
// (held_process.hpp); an IMU faster than the model's rate is refused. The first p samples come
// from the stationary distribution (Cholesky factor of the Toeplitz autocovariance), so there is no
// start-up transient to burn in. An unstable polynomial is refused, naming its largest pole.
#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <sstream>

#include "common/limits.hpp"
#include "errormodels/ar_model.hpp"
#include "errormodels/held_process.hpp"

namespace sinsim::errormodels {
namespace {

constexpr int kMaxOrder = limits::kMaxArOrder;

class ArState final : public HeldProcessState {
 public:
  ArState(int axis, double rate, const std::vector<double>& a, double sigmaE,
          const Eigen::MatrixXd& L, NormalStream s, NormalStream init)
      : HeldProcessState(axis, rate), p_(int(a.size())), sigmaE_(sigmaE), s_(s) {
    for (int i = 0; i < p_; ++i) negA_[i] = -a[i];
    // hist_[i] = y[n-1-i]; stationary draw of the p past values.
    Eigen::VectorXd z(p_);
    for (int i = 0; i < p_; ++i) z(i) = init.next();
    Eigen::VectorXd y0 = L * z;
    for (int i = 0; i < p_; ++i) hist_[i] = y0(i);
  }

 protected:
  // The oldest terms are summed first and y[n-1] last: the chain from one sample to the next is
  // then one multiply-add, not p of them (the recursion's latency bounds its speed).
  double next() override {
    double y = sigmaE_ * s_.next();
    for (int i = p_ - 1; i >= 0; --i) y += negA_[i] * hist_[i];
    for (int i = p_ - 1; i > 0; --i) hist_[i] = hist_[i - 1];
    hist_[0] = y;
    return y;
  }

  // The same recursion in blocks, the history in registers for the common orders (the sum is
  // formed in the same order as next(), so both give the same bits).
  void generate(double* out, int n) override {
    switch (p_) {
      case 1: return run<1>(out, n);
      case 2: return run<2>(out, n);
      case 3: return run<3>(out, n);
      case 4: return run<4>(out, n);
      case 5: return run<5>(out, n);
      case 6: return run<6>(out, n);
      case 7: return run<7>(out, n);
      case 8: return run<8>(out, n);
      default:
        for (int i = 0; i < n; ++i) out[i] = next();
    }
  }

 private:
  template <int P>
  void run(double* out, int n) {
    double h[P], a[P];
    for (int i = 0; i < P; ++i) {
      h[i] = hist_[i];
      a[i] = negA_[i];
    }
    for (int k = 0; k < n; ++k) {
      double y = sigmaE_ * s_.next();
      for (int i = P - 1; i >= 0; --i) y += a[i] * h[i];
      for (int i = P - 1; i > 0; --i) h[i] = h[i - 1];
      h[0] = y;
      out[k] = y;
    }
    for (int i = 0; i < P; ++i) hist_[i] = h[i];
  }

  int p_;
  double sigmaE_;
  NormalStream s_;
  double negA_[kMaxOrder];
  double hist_[kMaxOrder];
};

class Ar final : public Effect {
 public:
  Ar(std::vector<double> a, double sigmaE, double rate)
      : a_(std::move(a)), sigmaE_(sigmaE), rate_(rate) {
    const int p = int(a_.size());
    auto r = ar::autocovariance(a_, sigmaE_, p);
    Eigen::MatrixXd T(p, p);
    for (int i = 0; i < p; ++i)
      for (int j = 0; j < p; ++j) T(i, j) = r[std::abs(i - j)];
    L_ = T.llt().matrixL();
  }
  std::unique_ptr<EffectState> instantiate(const InstanceContext& ctx) const override {
    requireRateAtLeastImu(rate_, ctx);
    return std::make_unique<ArState>(ctx.site->axis, rate_, a_, sigmaE_, L_, ctx.stream(0),
                                     ctx.stream(1));
  }

 private:
  std::vector<double> a_;
  double sigmaE_, rate_;
  Eigen::MatrixXd L_;
};

}  // namespace

const std::vector<ParamSchema>& paramsOf_ar() {
  static const std::vector<ParamSchema> p = {
      param("a", ParamKind::list, fixed(Dimension::none())).printed(10)
          .doc("a1..ap, arburg's polynomial without its leading 1 (1 to 64 coefficients)"),
      param("sigma", ParamKind::quantity, signal()).oneOf(1).positive()
          .doc("driving-noise standard deviation sigma_e (sqrt of arburg's variance e)"),
      param("output_sigma", ParamKind::quantity, signal()).oneOf(1).positive()
          .doc("or the stationary standard deviation of the output"),
      param("rate", ParamKind::quantity, fixed(Dimension::frequency())).positive().printed(10)
          .doc("the sample rate the coefficients hold at")};
  return p;
}

std::unique_ptr<Effect> buildEffect_ar(const EffectSpec& spec, const EffectSite&,
                                       SpecProblems& problems) {
  std::vector<double> a = valuesOf(spec, "a");
  if (a.empty() || int(a.size()) > kMaxOrder) {
    problems.add("a", "expected 1 to " + std::to_string(kMaxOrder) + " coefficients a1..ap, got " +
                          std::to_string(a.size()));
    return nullptr;
  }
  for (double v : a)
    if (!std::isfinite(v)) {
      problems.add("a", "expected finite coefficients");
      return nullptr;
    }
  auto poles = ar::poles(a);
  std::complex<double> worst = 0;
  for (const auto& z : poles)
    if (std::abs(z) > std::abs(worst)) worst = z;
  // Strictly inside the unit circle, with a margin for the rounding of printed coefficients:
  // a pole at |z| > 1 - 1e-9 has a correlation time over 1e9 samples — not a stationary model.
  if (!(std::abs(worst) < 1.0 - 1e-9)) {
    std::ostringstream s;
    s.precision(12);  // |z| = 1 - 1e-10 must not print as "1"
    s << "unstable AR polynomial: largest pole magnitude " << std::abs(worst) << " (pole "
      << worst.real() << (worst.imag() < 0 ? " - " : " + ") << std::abs(worst.imag())
      << "i); every pole of 1/A(z) must lie inside the unit circle (|z| < 1). Check the sign "
         "convention: A(z) = 1 + a1 z^-1 + ... + ap z^-p, as MATLAB arburg returns it";
    problems.add("a", s.str());
    return nullptr;
  }
  const double sigma = arDrivingSigmaOf(spec);
  return std::make_unique<Ar>(std::move(a), sigma, valueOr(spec, "rate", NAN));
}

double arDrivingSigmaOf(const EffectSpec& spec) {
  if (!spec.has("output_sigma")) return valueOr(spec, "sigma", NAN);
  return valueOr(spec, "output_sigma", NAN) / std::sqrt(ar::varianceGain(valuesOf(spec, "a")));
}

}  // namespace sinsim::errormodels
