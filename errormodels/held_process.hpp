// A discrete-time process generated at its own rate and held over each of its sample periods
// (zero-order hold), integrated exactly over each IMU interval — what a real IMU does when its
// internal sensor rate is faster than its output rate and it outputs integrated increments.
// Works for any ratio of process rate to IMU rate ≥ 1 (integer or not); slower processes are
// refused at instantiation (requireRateAtLeastImu), because holding one value across several IMU
// intervals would invent a correlation the model does not have.
#pragma once

#include "errormodels/effect.hpp"

namespace sinsim::errormodels {

class HeldProcessState : public DirectAxisErrorState<HeldProcessState> {
 public:
  /// rate [Hz] of the process samples.
  HeldProcessState(int axis, double rate) : DirectAxisErrorState(axis), h_(1.0 / rate) {}

  double integral(const Interval& iv) final {
    if (!started_) {
      start_ = iv.t0;
      y_ = take();
      started_ = true;
    }
    // Times relative to the first interval's start; sample k holds over [k h, (k+1) h).
    const double b = iv.t1 - start_;
    const double eps = 1e-6 * h_;  // edges closer than this coincide (rounding of t, not physics)
    double t = iv.t0 - start_;
    double acc = 0.0;
    for (;;) {
      const double edge = double(k_ + 1) * h_;
      if (edge > b + eps) return acc + y_ * (b - t);
      if (edge >= b - eps) {
        acc += y_ * (b - t);
        ++k_;
        y_ = take();
        return acc;
      }
      acc += y_ * (edge - t);
      t = edge;
      ++k_;
      y_ = take();
    }
  }

 protected:
  /// The next process sample [signal units, SI].
  virtual double next() = 0;
  /// The next n samples, in order (the same values n calls of next() give). Processes override it
  /// with a tight loop: one virtual call per block instead of per sample.
  virtual void generate(double* y, int n) {
    for (int i = 0; i < n; ++i) y[i] = next();
  }

 private:
  static constexpr int kBuffer = 64;
  double take() {
    if (pos_ == kBuffer) {
      generate(buf_, kBuffer);
      pos_ = 0;
    }
    return buf_[pos_++];
  }

  double h_;
  double start_ = 0.0;
  std::uint64_t k_ = 0;
  double y_ = 0.0;
  bool started_ = false;
  int pos_ = kBuffer;
  double buf_[kBuffer];
};

}  // namespace sinsim::errormodels
