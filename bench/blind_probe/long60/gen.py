#!/usr/bin/python3
"""Own static 6-channel IMU record generator (NumPy only, no sinsim code).

usage: gen.py SENSOR SEED OUT.csv [--clean] [--plan K]
  SENSOR A: 100 Hz, 2 h. gx,gy,gz white+GM(tau 100 s); ax,ay white+random walk; az white+flicker(sum of GMs)
  SENSOR C: 100 Hz, 3 h. gyros white+rate random walk; accels AR(2)+white
  SENSOR B: 400 Hz, 1 h. gx,gy AR(2)+white; gz white+flicker; ax,ay,az white+GM(tau 30 s)
Writes OUT.csv (t[s], gx..gz [rad/s], ax..az [m/s^2]) and OUT.json (the hidden effects, sizes, times).
Effect size s (2 or 5): the effect alone has s x the base's Allan deviation at its characteristic tau
(outliers: amplitude s*5 sample sd; quantization: LSB = s*0.5 sample sd of the base).
"""
import sys, json
import numpy as np
from scipy.signal import lfilter

OMEGA = 7.2921150e-5
LAT = np.deg2rad(51.0)
G = 9.81

SENSORS = {
    'A': dict(fs=100.0, T=7200.0),
    'B': dict(fs=400.0, T=3600.0),
    'C': dict(fs=100.0, T=10800.0),
}
CAT = ['random_walk', 'ramp', 'warmup', 'sinusoid', 'bias_jumps', 'gauss_markov', 'outliers', 'quantization']
OOC = ['telegraph', 'noise_burst']


def gm(rng, n, fs, sigma, tau):
    phi = np.exp(-1.0 / (fs * tau))
    w = rng.standard_normal(n) * sigma * np.sqrt(1 - phi ** 2)
    x = lfilter([1.0], [1.0, -phi], w)
    return x


def flicker(rng, n, fs, B):
    # my 1/f: sum of GMs with taus log-spaced 0.5 s .. 5000 s, equal variance each -> ~flat Allan floor
    taus = np.logspace(np.log10(0.5), np.log10(5000), 9)
    out = np.zeros(n)
    for t in taus:
        out += gm(rng, n, fs, 1.0, t)
    return out * B / 0.9  # rough scaling (floor ~ B)


def adev(x, fs, tau):
    m = max(1, int(round(tau * fs)))
    n = len(x)
    if 2 * m >= n:
        m = n // 3
    c = np.concatenate(([0.0], np.cumsum(x)))
    mean = (c[m:] - c[:-m]) / m
    d = mean[m:] - mean[:-m]
    return np.sqrt(0.5 * np.mean(d ** 2))


def base(sensor, ch, rng, n, fs):
    if sensor == 'A':
        if ch in ('gx', 'gy', 'gz'):
            N = np.deg2rad(0.3) / 60.0  # 0.3 deg/sqrt(h) in rad/s/sqrt(Hz)
            return rng.standard_normal(n) * N * np.sqrt(fs) + gm(rng, n, fs, np.deg2rad(10.0 / 3600), 100.0)
        if ch in ('ax', 'ay'):
            V = 0.05 / 60.0  # 0.05 m/s/sqrt(h)
            K = 2e-5         # m/s^2/sqrt(s)
            return rng.standard_normal(n) * V * np.sqrt(fs) + np.cumsum(rng.standard_normal(n)) * K / np.sqrt(fs)
        V = 0.05 / 60.0
        return rng.standard_normal(n) * V * np.sqrt(fs) + flicker(rng, n, fs, 2e-4)
    elif sensor == 'C':
        if ch[0] == 'g':
            N = np.deg2rad(0.5) / 60.0
            K = np.deg2rad(2.0 / 3600) / 60.0 * 1.0  # rate random walk 2 deg/h/sqrt(h)
            return rng.standard_normal(n) * N * np.sqrt(fs) + np.cumsum(rng.standard_normal(n)) * K / np.sqrt(fs)
        e = rng.standard_normal(n) * 2e-4
        return lfilter([1.0], [1.0, -1.2, 0.35], e) + rng.standard_normal(n) * 5e-4
    else:
        if ch in ('gx', 'gy'):
            # AR(2) x_k = 1.5 x_{k-1} - 0.6 x_{k-2} + e, sd of x about 0.02 deg/s; plus white
            e = rng.standard_normal(n) * np.deg2rad(0.004)
            return lfilter([1.0], [1.0, -1.5, 0.6], e) + rng.standard_normal(n) * np.deg2rad(0.01)
        if ch == 'gz':
            N = np.deg2rad(0.15) / 60.0
            return rng.standard_normal(n) * N * np.sqrt(fs) + flicker(rng, n, fs, np.deg2rad(3.0 / 3600))
        V = 0.03 / 60.0
        return rng.standard_normal(n) * V * np.sqrt(fs) + gm(rng, n, fs, 1.5e-4, 30.0)


def effect_shape(kind, rng, n, fs, T):
    """unit-size shape of the effect, its characteristic tau, and event info"""
    t = np.arange(n) / fs
    info = {}
    if kind == 'random_walk':
        return np.cumsum(rng.standard_normal(n)), T / 10, info
    if kind == 'ramp':
        return t * rng.choice([-1, 1]), T / 10, info
    if kind == 'warmup':
        tw = 200.0
        info['tau_s'] = tw
        return rng.choice([-1, 1]) * np.exp(-t / tw), tw, info
    if kind == 'sinusoid':
        f = float(np.exp(rng.uniform(np.log(0.05), np.log(2.0))))
        info['freq_hz'] = f
        return np.sin(2 * np.pi * f * t + rng.uniform(0, 2 * np.pi)), 0.371 / f, info
    if kind == 'bias_jumps':
        ts = float(rng.uniform(0.05, 0.95) * T)
        info['t_step_s'] = ts
        return rng.choice([-1, 1]) * (t >= ts).astype(float), T / 10, info
    if kind == 'gauss_markov':
        tg = 5.0
        info['tau_s'] = tg
        return gm(rng, n, fs, 1.0, tg), 1.89 * tg, info
    if kind == 'telegraph':
        dwell = 300.0
        sw = rng.random(n) < 1.0 / (dwell * fs)
        info['switches'] = int(sw.sum())
        info['switch_t_s'] = (np.nonzero(sw)[0] / fs).round(1).tolist()
        return np.where(np.cumsum(sw) % 2 == 0, 1.0, -1.0), dwell, info
    if kind == 'noise_burst':
        t0 = float(rng.uniform(0.1, 0.7) * T)
        info['window_s'] = [t0, t0 + 0.2 * T]
        mask = (t >= t0) & (t < t0 + 0.2 * T)
        return rng.standard_normal(n) * mask, 1.0 / fs, info
    raise ValueError(kind)


def plan(sensor, seed, clean):
    """per channel list of (effect, size)"""
    chans = ['gx', 'gy', 'gz', 'ax', 'ay', 'az']
    if clean:
        return {c: [] for c in chans}
    rng = np.random.default_rng(1000 + seed)
    p = {}
    for i, c in enumerate(chans):
        k = (seed + i) % 3
        pool = CAT + OOC if rng.random() < 0.25 else CAT
        effs = list(rng.choice(pool, size=k, replace=False))
        p[c] = [(str(e), float(rng.choice([2.0, 5.0]))) for e in effs]
    return p


def main():
    sensor, seed, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    clean = '--clean' in sys.argv
    cfg = SENSORS[sensor]
    fs, T = cfg['fs'], cfg['T']
    n = int(round(fs * T))
    rng = np.random.default_rng(seed)
    chans = ['gx', 'gy', 'gz', 'ax', 'ay', 'az']
    pl = plan(sensor, seed, clean)
    ideal = {'gx': OMEGA * np.cos(LAT), 'gy': 0.0, 'gz': OMEGA * np.sin(LAT), 'ax': 0.0, 'ay': 0.0, 'az': G}
    bias = {c: (np.deg2rad(rng.normal(0, 0.05)) if c[0] == 'g' else rng.normal(0, 0.02)) for c in chans}
    cols = {}
    manifest = {'sensor': sensor, 'seed': seed, 'fs': fs, 'T': T, 'n': n, 'channels': {}}
    for c in chans:
        x = base(sensor, c, rng, n, fs)
        sd = x.std()
        effs = []
        quant = None
        for (kind, s) in pl[c]:
            if kind == 'quantization':
                quant = s * 0.5 * sd
                effs.append({'effect': kind, 'size': s, 'lsb': quant})
                continue
            if kind == 'outliers':
                k = 30
                idx = rng.choice(n, size=k, replace=False)
                y = np.zeros(n)
                y[idx] = rng.choice([-1, 1], size=k) * s * 5 * sd
                x = x + y
                effs.append({'effect': kind, 'size': s, 'amp': s * 5 * sd, 'count': k, 't_s': sorted((idx / fs).round(2).tolist())})
                continue
            shape, tc, info = effect_shape(kind, rng, n, fs, T)
            if kind == 'noise_burst':
                amp = s * adev(x, fs, tc) / np.sqrt(0.2)
            else:
                amp = s * adev(x, fs, tc) / max(adev(shape, fs, tc), 1e-300)
            x = x + amp * shape
            d = {'effect': kind, 'size': s, 'amp': float(amp), 'tau_c': float(tc)}
            d.update(info)
            effs.append(d)
        x = x + ideal[c] + bias[c]
        if quant is not None:
            x = np.round(x / quant) * quant
        cols[c] = x
        manifest['channels'][c] = effs
    t = np.arange(n) / fs
    arr = np.column_stack([t] + [cols[c] for c in chans])
    hdr = 't[s],gx[rad/s],gy[rad/s],gz[rad/s],ax[m/s^2],ay[m/s^2],az[m/s^2]'
    np.savetxt(out, arr, fmt=['%.4f'] + ['%.10e'] * 6, delimiter=',', header=hdr, comments='')
    with open(out.rsplit('.', 1)[0] + '.json', 'w') as f:
        json.dump(manifest, f, indent=1)


if __name__ == '__main__':
    main()
