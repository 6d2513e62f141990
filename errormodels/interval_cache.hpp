// Per-interval-length coefficients of an error process, kept for the last two interval lengths.
// IMU intervals are t_{k+1} − t_k with t_k = k/f, which alternate between a handful of values in
// their last bits (20 distinct ones over car.yaml's 207 800 intervals at 100 Hz): a one-entry
// cache misses on 21 % of the intervals there, two entries (most recent first) miss 21 times a run.
// The coefficients are a pure function of the length, so the values are the same either way.
#pragma once

#include <utility>

namespace sinsim::errormodels {

template <class Coefficients>
class IntervalCache {
 public:
  /// The coefficients for interval length dt [s], computed by make(dt) only when dt is neither of
  /// the last two lengths.
  template <class Make>
  const Coefficients& get(double dt, Make&& make) {
    if (dt != dt_[0]) {
      if (dt == dt_[1]) {
        std::swap(dt_[0], dt_[1]);
        std::swap(c_[0], c_[1]);
      } else {
        dt_[1] = dt_[0];
        c_[1] = c_[0];
        dt_[0] = dt;
        c_[0] = make(dt);
      }
    }
    return c_[0];
  }

 private:
  double dt_[2] = {-1.0, -1.0};  // [s]; −1: empty
  Coefficients c_[2] = {};
};

}  // namespace sinsim::errormodels
