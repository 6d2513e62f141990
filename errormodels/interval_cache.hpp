// Per-interval-length coefficients of an error process, kept for the last two interval lengths.
// IMU intervals are t_{k+1} − t_k with t_k = k/f, which alternate between a handful of values in
// their last bits (20 distinct ones over car.yaml's 207 800 intervals at 100 Hz): a one-entry
// cache misses on 21 % of the intervals there, two entries (the least recently used one replaced) miss 21 times a run.
// The coefficients are a pure function of the length, so the values are the same either way.
#pragma once


namespace sinsim::errormodels {

template <class Coefficients>
class IntervalCache {
 public:
  /// The coefficients for interval length dt [s], computed by make(dt) only when dt is neither of
  /// the last two lengths.
  template <class Make>
  const Coefficients& get(double dt, Make&& make) {
    if (dt == dt_[last_]) return c_[last_];
    last_ ^= 1;  // the other entry: a hit, or the least recently used one, replaced
    if (dt != dt_[last_]) {
      dt_[last_] = dt;
      c_[last_] = make(dt);
    }
    return c_[last_];
  }

 private:
  double dt_[2] = {-1.0, -1.0};  // [s]; −1: empty
  Coefficients c_[2] = {};
  int last_ = 0;  // the entry used last
};

}  // namespace sinsim::errormodels
