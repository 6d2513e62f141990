// Statistics of one series and the Monte Carlo realisations of a model (diagnose.hpp).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

#include "common/error.hpp"
#include "errormodels/diagnose/internal.hpp"
#include "errormodels/stats/allan.hpp"
#include "errormodels/stats/spectrum.hpp"
#include "common/types.hpp"

namespace sinsim::errormodels::diagnose::detail {

const std::array<const char*, 6> kChannels = {"gx", "gy", "gz", "ax", "ay", "az"};

int channelIndex(const std::string& name) {
  for (int c = 0; c < 6; ++c)
    if (name == kChannels[c]) return c;
  throw InputError("unknown channel \"" + name + "\" (known: gx, gy, gz, ax, ay, az)");
}

const std::vector<double>& channelData(const Record& r, int c) {
  return c < 3 ? r.gyro[c] : r.accel[c - 3];
}

Setup makeSetup(double rate, std::size_t n, const DiagnoseOptions& o) {
  Setup s;
  s.rate = rate;
  s.n = n;
  const auto maxM = std::max<std::size_t>(1, std::size_t(double(n) * o.maxFactorFraction));
  // Half-octave grid m = round(2^(j/2)): twice the points of the octave grid, so that "the
  // fraction of tau outside a 95 % band" is not decided by one or two points.
  for (int j = 0;; ++j) {
    const auto m = std::size_t(std::llround(std::pow(2.0, 0.5 * j)));
    if (m > maxM) break;
    if (s.factors.empty() || m != s.factors.back()) s.factors.push_back(m);
  }
  std::size_t L = o.psdSegment;
  if (L == 0) {
    L = 16;
    while (L * 2 <= n / 8 && L * 2 <= 4096) L *= 2;
  }
  if (L > n) throw InputError("PSD segment of " + std::to_string(L) + " samples exceeds the record");
  s.psdSegment = L;
  // Log-spaced bands over bins 1..L/2 (DC left out: every segment's mean is removed).
  const std::size_t kMax = L / 2;
  const double lo = std::log(1.0), hi = std::log(double(kMax) + 1.0);
  std::vector<std::size_t> current;
  std::size_t band = 0;
  const std::size_t nb = std::max<std::size_t>(4, o.psdBands);
  for (std::size_t k = 1; k <= kMax; ++k) {
    const auto b = std::min(nb - 1, std::size_t((std::log(double(k)) - lo) / (hi - lo) * double(nb)));
    if (b != band && !current.empty()) {
      s.psdBandBins.push_back(current);
      current.clear();
    }
    band = b;
    current.push_back(k);
  }
  if (!current.empty()) s.psdBandBins.push_back(current);
  for (const auto& bins : s.psdBandBins) {
    double f = 0;
    for (auto k : bins) f += double(k);
    s.psdBandFreq.push_back(f / double(bins.size()) * rate / double(L));
  }
  s.acfLags = o.acfMaxLag ? o.acfMaxLag : std::min<std::size_t>(n / 20, 500);
  s.acfLags = std::max<std::size_t>(1, std::min(s.acfLags, L / 4));
  return s;
}

std::vector<double> allanVariance(const std::vector<double>& y, const Setup& s) {
  AllanOptions ao;
  ao.factors = s.factors;
  ao.confidence_intervals = false;
  const auto c = allanDeviation(y, s.rate, AllanVariant::Overlapping, ao);
  std::vector<double> v(c.dev.size());
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = c.dev[i] * c.dev[i];
  return v;
}

SeriesStats seriesStats(const std::vector<double>& y, const Setup& s) {
  SeriesStats out;
  out.avar = allanVariance(y, s);
  WelchOptions wo;
  wo.segment_length = s.psdSegment;
  const auto p = welchPsd(y, s.rate, wo);
  for (const auto& bins : s.psdBandBins) {
    double sum = 0;
    for (auto k : bins) sum += p.psd[k];
    out.psd.push_back(sum / double(bins.size()));
  }
  // ACF from the averaged Welch spectrum (Wiener-Khinchin): r(k) = df [P0 + P_{L/2} (-1)^k +
  // sum_{j=1}^{L/2-1} P_j cos(2 pi j k / L)], divided by the window's normalised autocorrelation
  // w2(k) = sum w_n w_{n+k} / sum w_n^2 (the taper's bias; Percival & Walden 1993 sec. 6.18), then
  // by r(0). Costs O(L lags) instead of an FFT of the whole record, and treats the measurement
  // and every realisation alike. Lags are limited to L/4, where w2 >= 0.6.
  const std::size_t L = s.psdSegment, half = L / 2;
  std::vector<double> w(L), w2(s.acfLags + 1, 0.0);
  for (std::size_t n = 0; n < L; ++n) w[n] = 0.5 - 0.5 * std::cos(2 * M_PI * double(n) / double(L));
  for (std::size_t k = 0; k <= s.acfLags; ++k)
    for (std::size_t n = 0; n + k < L; ++n) w2[k] += w[n] * w[n + k];
  std::vector<double> cosTable(L);
  for (std::size_t m = 0; m < L; ++m) cosTable[m] = std::cos(2 * M_PI * double(m) / double(L));
  out.acf.assign(s.acfLags + 1, 0.0);
  for (std::size_t k = 0; k <= s.acfLags; ++k) {
    double r = p.psd[0] + p.psd[half] * (k % 2 ? -1.0 : 1.0);
    for (std::size_t j = 1; j < half; ++j) r += p.psd[j] * cosTable[(j * k) % L];
    out.acf[k] = r / (w2[k] / w2[0]);
  }
  const double r0 = out.acf[0];
  for (double& v : out.acf) v = r0 > 0 ? v / r0 : 0.0;
  return out;
}

void simulate(const ImuErrorModel& model, double rate, std::size_t n,
              const std::vector<double>& ideal, const std::vector<double>& temperatureK,
              std::uint64_t seed, std::uint64_t run, const std::vector<int>& channels,
              std::array<std::vector<double>, 6>& out) {
  auto corruptor = model.instantiate(rate, {seed, run});
  const double dt = 1.0 / rate;
  const Vec3 dtheta(ideal[0] * dt, ideal[1] * dt, ideal[2] * dt);
  const Vec3 dv(ideal[3] * dt, ideal[4] * dt, ideal[5] * dt);
  for (int c : channels) out[c].resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    ImuSample s;
    s.t = double(k + 1) * dt;
    s.dt = dt;
    s.dtheta_b = dtheta;
    s.dv_b = dv;
    corruptor->corrupt(s, temperatureK.empty() ? NAN : temperatureK[k]);
    for (int c : channels) out[c][k] = (c < 3 ? s.dtheta_b[c] : s.dv_b[c - 3]) / dt;
  }
}

McResult monteCarlo(const ImuErrorModel& model, const Record& record,
                    const std::vector<int>& channels, const Setup& setup,
                    const DiagnoseOptions& o) {
  std::vector<double> ideal(6, 0.0);
  for (int c = 0; c < 6; ++c) {
    const auto& y = channelData(record, c);
    if (y.empty()) continue;
    double m = 0;
    for (double v : y) m += v;
    ideal[c] = m / double(y.size());
  }
  const std::size_t R = o.realisations;
  McResult res;
  res.perChannel.assign(channels.size(), std::vector<SeriesStats>(R));
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::atomic<bool> failed{false};
  auto worker = [&] {
    std::array<std::vector<double>, 6> buf;
    for (;;) {
      const std::size_t r = next++;
      if (r >= R || failed) return;
      try {
        simulate(model, record.rate_hz, record.rows, ideal, record.temperature, o.seed, r,
                 channels, buf);
        for (std::size_t i = 0; i < channels.size(); ++i)
          res.perChannel[i][r] = seriesStats(buf[channels[i]], setup);
      } catch (...) {
        if (!failed.exchange(true)) failure = std::current_exception();
        return;
      }
    }
  };
  unsigned nt = o.threads ? o.threads : std::max(1u, std::thread::hardware_concurrency());
  nt = unsigned(std::min<std::size_t>(nt, R));
  std::vector<std::thread> pool;
  for (unsigned i = 1; i < nt; ++i) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  return res;
}

}  // namespace sinsim::errormodels::diagnose::detail
