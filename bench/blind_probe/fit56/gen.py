#!/usr/bin/python3
"""Independent static-IMU record generator. usage: gen.py CASE SEED OUT.csv [--rate 100] [--dur 1200] [--accel-g]
Truth written to OUT.truth.json (SI units)."""
import sys, json, numpy as np, argparse
p = argparse.ArgumentParser()
p.add_argument('case'); p.add_argument('seed', type=int); p.add_argument('out')
p.add_argument('--rate', type=float, default=100.0); p.add_argument('--dur', type=float, default=1200.0)
p.add_argument('--gm-tau', type=float, default=None); p.add_argument('--gm-sig', type=float, default=20.0, help='deg/h (gyro), x10 SI for accel')
p.add_argument('--accel-g', action='store_true', help='write accel in g but header says m/s^2')
a = p.parse_args()
rng = np.random.default_rng(a.seed)
dt = 1.0 / a.rate; n = int(round(a.dur * a.rate))
D2R = np.pi / 180
# realistic MEMS gyro sizes (SI); accel = 10x gyro numbers in m/s^2
N_g = 0.3 * D2R / 60            # 0.3 deg/sqrt(h)
def gm(sig, tau):
    phi = np.exp(-dt / tau); q = sig * np.sqrt(1 - phi**2)
    from scipy.signal import lfilter
    w = rng.standard_normal(n) * q
    x0 = rng.standard_normal() * sig
    y, _ = lfilter([1.0], [1.0, -phi], w, zi=[phi * x0])
    return y
def rw(K):
    return np.cumsum(rng.standard_normal(n) * K * np.sqrt(dt))
def flicker(B):
    # one-sided PSD B^2/(2 pi f) via FFT filtering on a 8x longer sequence, then a random window
    m = 8 * n; m2 = 1 << int(np.ceil(np.log2(m)))
    f = np.fft.rfftfreq(m2, dt)
    S = np.zeros_like(f); S[1:] = B**2 / (2 * np.pi * f[1:])
    # one-sided S: var = int S df ; complex coef amplitude
    X = (rng.standard_normal(len(f)) + 1j * rng.standard_normal(len(f))) * np.sqrt(S * m2 / (4 * dt))
    X[0] = 0; X[-1] = X[-1].real * np.sqrt(2)
    x = np.fft.irfft(X, m2)
    s = rng.integers(0, m2 - n)
    return x[s:s + n]
chans = ['gx', 'gy', 'gz', 'ax', 'ay', 'az']
taus = [1.0, 3.0, 10.0, 30.0, 60.0, 100.0]
truth = {}; data = {}
lat = 45 * D2R; Om = 7.292115e-5; g = 9.80665
ideal = {'gx': Om*np.cos(lat), 'gy': 0.0, 'gz': -Om*np.sin(lat), 'ax': 0.0, 'ay': 0.0, 'az': -g}
for i, c in enumerate(chans):
    s = 1.0 if c[0] == 'g' else 10.0
    N = N_g * s; tr = {'white_density': N}
    y = rng.standard_normal(n) * N / np.sqrt(dt)
    case = a.case
    if case in ('wgm', 'wgmrw', 'wgmrw2', 'wgmq'):
        sig = a.gm_sig * D2R / 3600 * s; tau = a.gm_tau if a.gm_tau else taus[i]
        y += gm(sig, tau); tr['gm_sigma'] = sig; tr['gm_tau'] = tau
        if case in ('wgmrw', 'wgmrw2'):
            K = (30 if case == 'wgmrw' else 150) * D2R / 3600 / 60 * s; y += rw(K); tr['rw_K'] = K
    elif case == 'w2gm':
        t1 = [0.5, 1, 2, 3, 5, 8][i]; t2 = 10 * t1
        s1 = 30 * D2R / 3600 * s; s2 = 20 * D2R / 3600 * s
        y += gm(s1, t1) + gm(s2, t2)
        tr.update(gm1_sigma=s1, gm1_tau=t1, gm2_sigma=s2, gm2_tau=t2)
    elif case in ('wflrw', 'wflrw2', 'wflrw3'):
        B = 10 * D2R / 3600 * s; K = {'wflrw': 30, 'wflrw2': 150, 'wflrw3': 70}[case] * D2R / 3600 / 60 * s
        y += flicker(B) + rw(K); tr.update(flicker_B=B, rw_K=K)
    elif case in ('qw', 'wgmq'):
        pass
    elif case == 'wdrift':
        R = 40 * D2R / 3600 / 3600 * s * (1 if i % 2 == 0 else -1)
        y += R * (np.arange(1, n + 1) * dt); tr['ramp_slope'] = R
    elif case == 'white':
        pass
    else:
        raise SystemExit('unknown case')
    y = y + ideal[c]
    if case in ('qw', 'wgmq'):
        lsb = 2e-5 * s   # increment LSB [rad] or [m/s]
        inc = np.cumsum(y * dt)
        q = np.round(inc / lsb) * lsb
        y = np.diff(np.concatenate([[0.0], q])) / dt
        tr['quant_lsb_increment'] = lsb; tr['quant_Q'] = lsb / np.sqrt(12)
    data[c] = y; truth[c] = tr
t = np.arange(1, n + 1) * dt
if a.accel_g:
    for c in ['ax', 'ay', 'az']: data[c] = data[c] / g
hdr = 't [s],gx [rad/s],gy [rad/s],gz [rad/s],ax [m/s^2],ay [m/s^2],az [m/s^2],temp [degC]'
M = np.column_stack([t] + [data[c] for c in chans] + [np.full(n, 25.0)])
np.savetxt(a.out, M, delimiter=',', header=hdr, comments='', fmt='%.10g')
json.dump({'case': a.case, 'seed': a.seed, 'rate': a.rate, 'dur': a.dur, 'truth': truth}, open(a.out + '.truth.json', 'w'), indent=1)
