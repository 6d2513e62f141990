#!/usr/bin/python3
"""Own static-IMU record generator with known truth (first-principles MEMS error models).
Writes CSV t [s], gx..gz [rad/s], ax..az [m/s^2] and a matching sinsim model YAML (truth).
usage: gen.py SENSOR SEED DURATION_S OUTDIR   (SENSOR in S1..S4)"""
import sys, numpy as np
D2R = np.pi/180; H = 3600.0
OMEGA = 7.292115e-5
def normal_gravity(lat):  # Somigliana WGS-84, at h=0
    s2 = np.sin(lat)**2
    return 9.7803253359*(1+0.00193185265241*s2)/np.sqrt(1-0.00669437999013*s2)

# Truth sets, per sensor: gyro units rad/s based, accel m/s^2 based (SI); yaml strings alongside.
UG = 9.80665e-6
SENSORS = {
 # white + 1st-order GM + random walk (industrial MEMS)
 'S1': dict(gyro=dict(N=0.25*D2R/60, gm=[(6*D2R/H, 150.0)], K=4*D2R/H/np.sqrt(H)),
            accel=dict(N=0.05/60, gm=[(60*UG, 300.0)], K=30e-6/np.sqrt(H)*1.0)),
 # white + flicker (own FFT 1/f) (consumer MEMS)
 'S2': dict(gyro=dict(N=0.6*D2R/60, B=12*D2R/H),
            accel=dict(N=0.12/60, B=50*UG)),
 # white + quantization (rate LSB), coarse LSB
 'S3': dict(gyro=dict(N=1.0*D2R/60, lsb=0.2*D2R),
            accel=dict(N=0.2/60, lsb=5e-3*9.80665)),
 # white + two GMs a decade+ apart (tactical-grade MEMS)
 'S4': dict(gyro=dict(N=0.1*D2R/60, gm=[(3*D2R/H, 20.0), (2*D2R/H, 500.0)]),
            accel=dict(N=0.03/60, gm=[(40*UG, 30.0), (25*UG, 600.0)])),
}

def gm_series(rng, n, dt, sigma, tau):
    # exact discrete GM sampled at dt, then mean over interval approximated by sample (dt << tau)
    phi = np.exp(-dt/tau); q = sigma*np.sqrt(1-phi**2)
    w = rng.standard_normal(n)*q
    x = np.empty(n); x0 = rng.standard_normal()*sigma
    from scipy.signal import lfilter
    x, _ = lfilter([1.0], [1.0, -phi], w, zi=[phi*x0])
    return x

# NOTE: this shapes a ONE-sided PSD B^2/(2 pi f); sinsim/IEEE-952 'B' refers to the two-sided
# convention (white: AVAR=N^2/tau with S=N^2), so the generated flicker has an ADEV floor 0.664*B/sqrt(2)
# (checked numerically: 0.707 ratio). The truth YAML therefore writes B_eff = B/sqrt(2).
def flicker_series(rng, n, fs, B):
    # one-sided PSD S(f) = B^2/(2 pi f), built in the frequency domain on 2n samples, keep first n
    m = 2*n
    w = rng.standard_normal(m)
    W = np.fft.rfft(w)
    f = np.fft.rfftfreq(m, 1/fs)
    shape = np.zeros_like(f); shape[1:] = np.sqrt(B**2/(2*np.pi*f[1:]) * fs/2)  # white var1 -> PSD 2/fs
    x = np.fft.irfft(W*shape, m)[:n]
    return x

def gen_channel(rng, n, dt, p, ideal):
    e = p['N']/np.sqrt(dt)*rng.standard_normal(n)
    for (s, tau) in p.get('gm', []):
        e += gm_series(rng, n, dt, s, tau)
    if 'K' in p:
        # rate random walk: b_k = sum K sqrt(dt) w ; start 0
        e += np.cumsum(p['K']*np.sqrt(dt)*rng.standard_normal(n))
    if 'B' in p:
        e += flicker_series(rng, n, 1/dt, p['B'])
    y = ideal + e
    if 'lsb' in p:
        y = np.round(y/p['lsb'])*p['lsb']
    return y

def yaml_sensor(p, gyro):
    L = []
    if gyro:
        L.append(f"    - {{type: white, density: {p['N']/D2R*60:.9g} deg/sqrt(h)}}")
        for s, tau in p.get('gm', []):
            L.append(f"    - {{type: gauss_markov, sigma: {s/D2R*H:.9g} deg/h, tau: {tau:.9g} s}}")
        if 'K' in p: L.append(f"    - {{type: random_walk, K: {p['K']/D2R*H*np.sqrt(H):.9g} deg/h/sqrt(h)}}")
        if 'B' in p: L.append(f"    - {{type: bias_instability, B: {p['B']/np.sqrt(2)/D2R*H:.9g} deg/h, tau_range: [0.1 s, 3600 s]}}")
        if 'lsb' in p: L.append(f"    - {{type: quantization, lsb: {p['lsb']/D2R:.9g} deg/s}}")
    else:
        L.append(f"    - {{type: white, density: {p['N']*60:.9g} m/s/sqrt(h)}}")
        for s, tau in p.get('gm', []):
            L.append(f"    - {{type: gauss_markov, sigma: {s/UG:.9g} ug, tau: {tau:.9g} s}}")
        if 'K' in p: L.append(f"    - {{type: random_walk, K: {p['K']*np.sqrt(H):.9g} m/s^2/sqrt(h)}}")
        if 'B' in p: L.append(f"    - {{type: bias_instability, B: {p['B']/np.sqrt(2)/UG:.9g} ug, tau_range: [0.1 s, 3600 s]}}")
        if 'lsb' in p: L.append(f"    - {{type: quantization, lsb: {p['lsb']/9.80665*1e3:.9g} mg}}")
    return "\n".join(L)

def truth_yaml(name):
    s = SENSORS[name]
    return (f"description: probe63 truth {name}\n"
            f"gyro:\n  all:\n{yaml_sensor(s['gyro'], True)}\naccel:\n  all:\n{yaml_sensor(s['accel'], False)}\n")

if __name__ == '__main__':
    name, seed, dur, out = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
    fs = 100.0; dt = 1/fs; n = int(round(dur*fs))
    lat = 45*D2R
    rng = np.random.default_rng(1000*int(name[1]) + seed)
    g = normal_gravity(lat)
    # body = NED (level, facing north): omega_ib_b = [W cos lat, 0, -W sin lat], f_b = [0,0,-g]
    ideal_g = [OMEGA*np.cos(lat), 0.0, -OMEGA*np.sin(lat)]
    ideal_a = [0.0, 0.0, -g]
    s = SENSORS[name]
    cols = [gen_channel(rng, n, dt, s['gyro'], ideal_g[i]) for i in range(3)]
    cols += [gen_channel(rng, n, dt, s['accel'], ideal_a[i]) for i in range(3)]
    t = (np.arange(n)+1)*dt
    A = np.column_stack([t]+cols)
    fn = f"{out}/{name}_s{seed}.csv"
    np.savetxt(fn, A, delimiter=',', fmt=['%.2f']+['%.10e']*6,
               header="t [s],gx [rad/s],gy [rad/s],gz [rad/s],ax [m/s^2],ay [m/s^2],az [m/s^2]", comments='')
    open(f"{out}/{name}_truth.yaml", 'w').write(truth_yaml(name))
    print(fn)
