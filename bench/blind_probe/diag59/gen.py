#!/usr/bin/env python3
"""Own numpy generator of static gyro records (gx, gy, gz in rad/s) with optional hidden effects.
usage: gen.py OUT.csv --base KIND --seed S [--fx EFFECT:TARGET[,EFFECT:TARGET]] [--fz ...] [--rate 100] [--dur 900]
gy is always clean. Effects on gx (--fx) and gz (--fz).  Prints a JSON with effect visibility
(max over tau of ADEV(effect alone)/ADEV(base alone))."""
import numpy as np, sys, argparse, json
from scipy.signal import lfilter

EARTH = 7.292115e-5
def base_noise(kind, n, fs, rng, ch):
    dt = 1.0/fs
    sw = 1.0e-3 * (1 + 0.2*ch)           # white sd per sample [rad/s]
    x = sw*rng.standard_normal(n)
    if kind == 'wgm':      # white + 1st-order GM, tau 20 s
        tau, s = 20.0, 3e-4
        a = np.exp(-dt/tau); e = s*np.sqrt(1-a*a)*rng.standard_normal(n)
        g = lfilter([1], [1, -a], e); x += g
    elif kind == 'wrw':    # white + random walk
        K = 3e-5
        x += np.cumsum(K*np.sqrt(dt)*rng.standard_normal(n))
    elif kind == 'wfl':    # white + 1/f made by FFT shaping
        F = np.fft.rfftfreq(2*n, dt); w = rng.standard_normal(len(F)) + 1j*rng.standard_normal(len(F))
        w[0] = 0; w[1:] /= np.sqrt(F[1:])
        f = np.fft.irfft(w)[:n]; f *= 1.5e-4/np.std(f)
        x += f
    elif kind == 'ar2':    # AR(2) dominant + small white
        e = 1.5e-3*rng.standard_normal(n)
        x = 0.3*x + lfilter([1], [1, -1.5, 0.6], e)
    return x

def adev(y, fs):
    ms = np.unique(np.round(2**np.arange(0, np.log2(len(y)/8), 0.5)).astype(int))
    c = np.concatenate([[0], np.cumsum(y)]); out = []
    for m in ms:
        a = (c[m:] - c[:-m])/m
        d = a[m:] - a[:-m]
        out.append(np.sqrt(0.5*np.mean(d*d)))
    return ms/fs, np.array(out)

def effect(name, size, n, fs, rng, sref):
    """size is a dimensionless multiplier; sref = white sd of the channel"""
    t = np.arange(n)/fs; T = n/fs
    if name == 'ramp':        return size*2e-7*t                       # rad/s/s
    if name == 'sinusoid':    return size*0.25*sref*np.sin(2*np.pi*3.7*t + 1.0)
    if name == 'bias_jumps':  # two steps
        y = np.zeros(n); y[int(0.37*n):] += size*1e-4; y[int(0.71*n):] -= size*0.7e-4; return y
    if name == 'outliers':    # 0.05 Hz spikes
        y = np.zeros(n); k = rng.random(n) < 0.05/fs; y[k] = size*5*sref*rng.choice([-1, 1], k.sum()); return y
    if name == 'random_walk': return np.cumsum(size*1e-5*np.sqrt(1/fs)*rng.standard_normal(n))
    if name == 'gauss_markov':
        tau = 2.0; a = np.exp(-1/fs/tau); return lfilter([1], [1, -a], size*1e-4*np.sqrt(1-a*a)*rng.standard_normal(n))
    if name == 'warmup':      return size*3e-4*np.exp(-t/60.0)
    # --- out of catalogue ---
    if name == 'chirp':       # line whose frequency sweeps 2 -> 6 Hz
        f = 2 + 4*t/T; ph = 2*np.pi*np.cumsum(f)/fs
        return size*0.25*sref*np.sin(ph)
    if name == 'noiseburst':  # white noise variance x(1+size) for the middle 30 % (nonstationary)
        y = np.zeros(n); i0, i1 = int(0.35*n), int(0.65*n)
        y[i0:i1] = np.sqrt(size)*sref*rng.standard_normal(i1-i0); return y
    if name == 'triangle':    # slow thermal-cycle-like triangle wave, period T/3 (not a sinusoid)
        p = T/3; ph = (t % p)/p; return size*1e-4*(2*np.abs(2*ph-1)-1)
    if name == 'telegraph':   # random telegraph +-A, mean dwell 20 s
        y = np.ones(n); sw = rng.random(n) < (1/20.0)/fs; s = np.cumprod(np.where(sw, -1, 1)); return size*5e-5*s
    raise SystemExit('unknown effect ' + name)

VIS1 = {  # median max ADEV ratio effect/base at size 1 (scripts/calib.py, 100 Hz, 900 s)
 'wgm': dict(ramp=0.0765, sinusoid=0.598, bias_jumps=0.155, outliers=0.116, random_walk=0.334, gauss_markov=0.58, warmup=0.115, chirp=0.526, noiseburst=0.565, triangle=0.354, telegraph=0.208),
 'wrw': dict(ramp=0.0823, sinusoid=0.599, bias_jumps=0.167, outliers=0.117, random_walk=0.333, gauss_markov=1.06, warmup=0.141, chirp=0.526, noiseburst=0.567, triangle=0.381, telegraph=0.469),
 'wfl': dict(ramp=0.257, sinusoid=0.59, bias_jumps=0.521, outliers=0.101, random_walk=0.997, gauss_markov=0.825, warmup=0.386, chirp=0.519, noiseburst=0.551, triangle=1.19, telegraph=0.519),
 'ar2': dict(ramp=0.0728, sinusoid=0.0471, bias_jumps=0.148, outliers=0.0822, random_walk=0.317, gauss_markov=0.158, warmup=0.109, chirp=0.0421, noiseburst=0.395, triangle=0.337, telegraph=0.147)}

def size_for(base, eff, target):
    if eff == 'quantization': return target
    v = VIS1[base][eff]
    return (target/v)**2 if eff == 'noiseburst' else target/v

def make_record(path, base, seed, fx=(), fz=(), rate=100.0, dur=900.0):
    """fx, fz: lists of (effect, target visibility). Returns visibility dict."""
    fs = rate; n = int(dur*fs); rng = np.random.default_rng(seed)
    cols = []; vis = {}
    for ch, name, spec in ((0, 'gx', fx), (1, 'gy', ()), (2, 'gz', fz)):
        b = base_noise(base, n, fs, rng, ch)
        sref = 1.0e-3*(1+0.2*ch)
        eff = np.zeros(n); q = None
        for nm, tgt in spec:
            if nm == 'quantization': q = tgt*sref; continue
            e = effect(nm, size_for(base, nm, tgt), n, fs, rng, sref); eff += e
            tb, ab = adev(b, fs); te, ae = adev(e, fs)
            vis[name + ':' + nm] = float(np.max(ae/ab))
        y = EARTH*[0.3, -0.5, 0.8][ch] + b + eff
        if q is not None:
            y = q*np.round(y/q); vis[name + ':quantization'] = float(np.std(y - (EARTH*[0.3, -0.5, 0.8][ch] + b + eff))/sref)
        cols.append(y)
    with open(path, 'w') as f:
        f.write('gx,gy,gz\n')
        np.savetxt(f, np.column_stack(cols), fmt='%.9e', delimiter=',')
    return vis

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('out'); ap.add_argument('--base', required=True); ap.add_argument('--seed', type=int, required=True)
    ap.add_argument('--fx', default='', help='EFFECT:TARGET[,EFFECT:TARGET] on gx; TARGET = max ADEV ratio effect/base')
    ap.add_argument('--fz', default='')
    ap.add_argument('--rate', type=float, default=100.0); ap.add_argument('--dur', type=float, default=900.0)
    a = ap.parse_args()
    p = lambda s: [(x.split(':')[0], float(x.split(':')[1])) for x in s.split(',') if x]
    print(json.dumps(make_record(a.out, a.base, a.seed, p(a.fx), p(a.fz), a.rate, a.dur)))

if __name__ == '__main__':
    main()
