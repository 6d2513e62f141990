// Helpers shared by the fitting tests: fixture reading and seeded AR simulation.
#pragma once

#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace fit_test {

/// Overlapping Allan variance of rate samples y at interval dt [s], averaging factor m, written
/// independently of errormodels/stats (NIST SP 1065 eq. 14, from the phase x_k = dt·Σ_{i<k} y_i).
inline double overlappingAvar(const std::vector<double>& y, double dt, std::size_t m) {
  std::vector<double> x(y.size() + 1, 0.0);
  for (std::size_t i = 0; i < y.size(); ++i) x[i + 1] = x[i] + y[i] * dt;
  const double tau = double(m) * dt;
  double s = 0.0;
  const std::size_t terms = x.size() - 2 * m;
  for (std::size_t i = 0; i < terms; ++i) {
    const double d = x[i + 2 * m] - 2 * x[i + m] + x[i];
    s += d * d;
  }
  return s / (2.0 * tau * tau * double(terms));
}

inline std::string fixturePath(const std::string& name) {
  return std::string(SINSIM_FIT_FIXTURES) + "/" + name;
}

inline std::vector<double> readColumn(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open fixture " + path);
  std::vector<double> v;
  double d;
  while (in >> d) v.push_back(d);
  return v;
}

/// Fixture lines "<series> <order> <demean> <field> v1 v2 ..." keyed by (series, order, demean,
/// field).
using FixtureKey = std::tuple<std::string, int, int, std::string>;
inline std::map<FixtureKey, std::vector<double>> readFixture(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open fixture " + path);
  std::map<FixtureKey, std::vector<double>> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    std::string series, field;
    int order = 0, demean = 0;
    s >> series >> order >> demean >> field;
    std::vector<double> v;
    double d;
    while (s >> d) v.push_back(d);
    out[{series, order, demean, field}] = v;
  }
  return out;
}

/// x[n] = -a1 x[n-1] - ... - ap x[n-p] + sigma w[n], w ~ N(0,1) from std::mt19937_64(seed)
/// (libstdc++'s normal_distribution is deterministic for a given engine state), with `burn`
/// samples discarded so the output is (near) stationary.
inline std::vector<double> simulateAr(const std::vector<double>& a, double sigma, std::size_t n,
                                      std::uint64_t seed, std::size_t burn = 20000) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> w(0.0, 1.0);
  const std::size_t p = a.size() - 1;
  std::vector<double> hist(p, 0.0);  // hist[i] = x[n-1-i]
  std::vector<double> out;
  out.reserve(n);
  for (std::size_t t = 0; t < n + burn; ++t) {
    double v = sigma * w(rng);
    for (std::size_t i = 0; i < p; ++i) v -= a[i + 1] * hist[i];
    for (std::size_t i = p; i-- > 1;) hist[i] = hist[i - 1];
    if (p > 0) hist[0] = v;
    if (t >= burn) out.push_back(v);
  }
  return out;
}

/// The seed paper's AR(5) table (ADIS16355, arburg convention [1 a2..a6]).
struct PaperAxis {
  const char* name;
  std::vector<double> a;
};
inline const std::vector<PaperAxis>& paperTable() {
  static const std::vector<PaperAxis> t = {
      {"Gx", {1.0, -1.0327, -0.34341, 0.037895, 0.19732, 0.14724}},
      {"Gy", {1.0, -1.2391, -0.063362, 0.091524, 0.13092, 0.086379}},
      {"Gz", {1.0, -1.0604, -0.30249, 0.043657, 0.18006, 0.14555}},
      {"Ax", {1.0, -0.51552, -0.068261, -0.047218, -0.049565, -0.13655}},
      {"Ay", {1.0, -0.46354, -0.078197, -0.077146, -0.020449, -0.062445}},
      {"Az", {1.0, -0.41897, -0.10907, -0.077718, -0.074069, -0.1431}},
  };
  return t;
}

}  // namespace fit_test
