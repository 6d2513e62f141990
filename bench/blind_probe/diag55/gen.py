#!/usr/bin/python3
"""Independent static-IMU record generator (numpy only).
Usage: gen.py --effect E --size S --seed N --rate HZ --dur SEC --chans gx,az --out PREFIX [--clean]
Writes PREFIX.csv (record), PREFIX.model.yaml (exact base model), PREFIX.truth.json.
Base per channel (drawn from seed): white+GM, white+RW, or white+AR(2), MEMS-sized.
Effects: none sinusoid ramp warmup steps telegraph outliers quant temp rw flicker
Size S: target max over tau of ADEV_effect/ADEV_base (outliers: amplitude in sample sd;
quant: LSB in sample sd)."""
import argparse, json, numpy as np
p = argparse.ArgumentParser()
p.add_argument('--effect', default='none'); p.add_argument('--size', type=float, default=4.0)
p.add_argument('--seed', type=int, default=1); p.add_argument('--rate', type=float, default=100.)
p.add_argument('--dur', type=float, default=1800.); p.add_argument('--chans', default='gx,az')
p.add_argument('--out', required=True); p.add_argument('--clean', action='store_true',
    help='same base parameters, fresh noise, no effect (for fit)')
p.add_argument('--base', default='mixed', help='mixed|gm|rw|ar|white')
p.add_argument('--tempcol', action='store_true', help='write a temp column even without temp effect')
a = p.parse_args()
fs = a.rate; dt = 1/fs; n = int(round(a.dur*fs)); t = (np.arange(n)+1)*dt
prm = np.random.default_rng(a.seed)            # parameters (shared by clean/effect record)
rng = np.random.default_rng(a.seed*1000 + (7 if a.clean else 0) + 13)
CH = ['gx','gy','gz','ax','ay','az']
def oadev(x, ms):
    c = np.concatenate([[0], np.cumsum(x)]); out = []
    for m in ms:
        if 2*m >= len(x): out.append(np.nan); continue
        mu = (c[m:] - c[:-m])/m
        d = mu[2*m - m:] - mu[:-m] if False else mu[m:] - mu[:-m]
        out.append(np.sqrt(0.5*np.mean(d*d)))
    return np.array(out)
ms = np.unique(np.round(2**np.arange(0, np.log2(n/8), 0.5)).astype(int))
# Earth rate + gravity at lat 45 deg, level, yaw 0 (NED = body)
Om = 7.292115e-5; lat = np.radians(45.); g = 9.80619920
ideal = dict(gx=Om*np.cos(lat), gy=0.0, gz=-Om*np.sin(lat), ax=0.0, ay=0.0, az=-g)
bases = {}; rec = {}; model = {'gyro': {}, 'accel': {}}
for c in CH:
    gyro = c[0] == 'g'
    N = prm.uniform(1e-4, 1e-3) if gyro else prm.uniform(1e-3, 1e-2)   # /sqrt(Hz) = SI*sqrt(s)
    kind = a.base if a.base != 'mixed' else prm.choice(['gm', 'rw', 'ar'])
    x = N*np.sqrt(fs)*rng.standard_normal(n)
    eff = [f"{{type: white, density: {N:.9g} {'rad/s' if gyro else 'm/s^2'}*sqrt(s)}}"]
    U = 'rad/s' if gyro else 'm/s^2'
    info = dict(kind=kind, N=N)
    if kind == 'gm':
        tau = 10**prm.uniform(np.log10(20*dt), np.log10(a.dur/30)); sig = N*prm.uniform(0.3, 2.0)/np.sqrt(tau)*3
        phi = np.exp(-dt/tau); w = rng.standard_normal(n)*sig*np.sqrt(1-phi**2)
        y = np.empty(n); y[0] = sig*rng.standard_normal()
        from scipy.signal import lfilter
        y[1:] = lfilter([1], [1, -phi], w[1:], zi=[phi*y[0]])[0]
        x += y; eff.append(f"{{type: gauss_markov, sigma: {sig:.9g} {U}, tau: {tau:.9g} s, rate: {fs:g} Hz}}")
        info.update(sig=sig, tau=tau)
    elif kind == 'rw':
        K = N*prm.uniform(0.005, 0.03)
        x += np.cumsum(K*np.sqrt(dt)*rng.standard_normal(n))
        eff.append(f"{{type: random_walk, K: {K:.9g} {U}/sqrt(s)}}"); info.update(K=K)
    elif kind == 'ar':
        from scipy.signal import lfilter
        r = prm.uniform(0.6, 0.95); th = prm.uniform(0.05, 1.0)
        a1, a2 = -2*r*np.cos(th), r*r
        sd = N*np.sqrt(fs)*prm.uniform(0.3, 1.0)
        y = lfilter([1], [1, a1, a2], sd*rng.standard_normal(n + 5000))[5000:]
        x += y; eff.append(f"{{type: ar, a: [{a1:.10g}, {a2:.10g}], sigma: {sd:.9g} {U}, rate: {fs:g} Hz}}")
        info.update(a=[a1, a2], sigma=sd)
    bias = (prm.normal(0, 5e-3) if gyro else prm.normal(0, 0.02))
    bases[c] = x; info['bias'] = bias; rec[c] = info
    model['gyro' if gyro else 'accel'][c[1]] = eff
# effects
temp = None; truth = dict(effect=a.effect, size=a.size, chans=[], params={})
targets = [] if (a.clean or a.effect == 'none') else a.chans.split(',')
Tk = 25 + 0*t
if a.effect == 'temp' or a.tempcol:
    # warming chamber: slow sinusoidal cycle + small noise (not smooth-in-time only)
    Tk = 25 + 8*np.sin(2*np.pi*t/(a.dur/2.3) + prm.uniform(0, 6)) + 0.05*rng.standard_normal(n)
    temp = Tk
for c in targets:
    x = bases[c]; sd1 = np.std(x); ab = oadev(x - x.mean(), ms)
    e = np.zeros(n); P = {}
    E = a.effect
    if E == 'sinusoid':
        f = 10**prm.uniform(np.log10(0.02), np.log10(fs/5)); ph = prm.uniform(0, 6.28)
        e = np.sin(2*np.pi*f*t + ph); P = dict(freq=f)
    elif E == 'ramp':
        e = t/a.dur; P = {}
    elif E == 'warmup':
        tau = prm.uniform(60, 300); e = np.exp(-t/tau); P = dict(tau=tau)
    elif E == 'steps':
        k = prm.integers(1, 4); ts = np.sort(prm.uniform(0.1, 0.9, k))*a.dur
        for ti in ts: e += prm.choice([-1, 1])*(t >= ti)
        P = dict(times=list(ts))
    elif E == 'telegraph':
        rate = prm.uniform(10, 40)/a.dur; s = 1.0; lev = 1; sw = 0
        u = rng.random(n) < rate*dt
        lev = np.cumsum(u) % 2; e = lev - 0.5; P = dict(rate=rate, switches=int(u.sum()))
    elif E == 'rw':
        e = np.cumsum(rng.standard_normal(n))*np.sqrt(dt)
    elif E == 'flicker':
        F = np.fft.rfftfreq(n, dt); F[0] = F[1]; Z = (rng.standard_normal(len(F)) + 1j*rng.standard_normal(len(F)))/np.sqrt(F)
        e = np.fft.irfft(Z, n)
    elif E == 'temp':
        e = (Tk - 25) + 0.02*(Tk - 25)**2
    if E in ('outliers',):
        rate = 0.02; k = rng.random(n) < rate*dt
        amp = a.size*sd1; e = np.where(k, amp*rng.choice([-1, 1], n), 0.0); P = dict(rate=rate, amp=amp, count=int(k.sum()))
        bases[c] = x + e
    elif E == 'quant':
        lsb = a.size*sd1; y = x + ideal[c] + rec[c]['bias']
        bases[c] = np.round(y/lsb)*lsb - ideal[c] - rec[c]['bias']; P = dict(lsb=lsb)
    else:
        ae = oadev(e - e.mean(), ms); scale = a.size/np.nanmax(ae/ab)
        bases[c] = x + scale*e; P['scale'] = scale
    truth['chans'].append(c); truth['params'][c] = P
# write
cols = ['t [s]'] + [f"{c} [{'rad/s' if c[0]=='g' else 'm/s^2'}]" for c in CH] + (['temp [degC]'] if temp is not None else [])
M = [t] + [bases[c] + ideal[c] + rec[c]['bias'] for c in CH] + ([temp] if temp is not None else [])
np.savetxt(a.out + '.csv', np.column_stack(M), delimiter=',', header=','.join(cols), comments='', fmt='%.12g')
with open(a.out + '.model.yaml', 'w') as f:
    f.write(f'description: "probe base seed {a.seed}"\n')
    for s in ('gyro', 'accel'):
        f.write(f'{s}:\n')
        for ax in 'xyz':
            f.write(f'  {ax}:\n')
            for e in model[s][ax]: f.write(f'    - {e}\n')
truth['base'] = rec
json.dump(truth, open(a.out + '.truth.json', 'w'), indent=1, default=float)
