#!/usr/bin/python3
"""A static-IMU record generator written blind (2026-12-06, fifty-third session) by a helper who
read only the README and docs, never the source or the other generators: a new user's probe of
`sinsim fit` and `sinsim diagnose`. Kept as written. usage: gen.py STYLE SEED EFFECT OUT.csv
STYLE: A (400 Hz, AA-filtered+decimated, ms time, deg/s & g, custom names)
       B (125 Hz, delta-angle quantised increments / dt, deg/h & mg, temp column, ';')
       C (800 Hz, no header-time, whitespace, rad/s & m/s^2, rate-quantised LSB)
EFFECT: none | temp | sine | step | outliers | rw | ramp | warmup"""
import sys, json, numpy as np
from scipy import signal
style, seed, effect, out = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
rng = np.random.default_rng(seed)
cfg = {'A': dict(fs=400., T=600., D=4, order=4, fc=0.3),
       'B': dict(fs=125., T=2000., D=4, order=3, fc=0.4),
       'C': dict(fs=800., T=300., D=2, order=2, fc=0.2)}[style]
fs, T, D = cfg['fs'], cfg['T'], cfg['D']
n = int(round(fs*T)); dt = 1/fs; t = np.arange(n)*dt
# truth, SI-ish: gyro in deg/s, accel in m/s^2
N_g = 0.25/60      # deg/s/sqrt(Hz)  (0.25 deg/sqrt(h))
B_g = 3.0/3600     # deg/s (3 deg/h)
K_g = 6.0/3600/60  # deg/s/sqrt(s)  (6 deg/h/sqrt(h))
N_a = 0.05/60      # m/s^2/sqrt(Hz) (0.05 m/s/sqrt(h))
B_a = 20e-6*9.80665
K_a = 0.002/60     # m/s^2/sqrt(s)
sos = signal.butter(cfg['order'], cfg['fc']/D, output='sos')  # cutoff rel. to high-rate Nyquist
def white_filtered(N):
    x = rng.standard_normal(n*D + 2000)*N*np.sqrt(fs*D)
    y = signal.sosfilt(sos, x)[2000:][::D]
    return y
def flicker(B, taus=np.logspace(-0.5, 3.2, 7)):
    # sum of GMs spanning decades; each with sigma so that the plateau ~ B
    s = np.zeros(n)
    for tau in taus:
        a = np.exp(-dt/tau); sig = B*0.75
        w = rng.standard_normal(n)*sig*np.sqrt(1-a*a)
        s += signal.lfilter([1.], [1., -a], w, zi=[rng.standard_normal()*sig*a])[0]
    return s
def rw(K):
    return np.cumsum(rng.standard_normal(n))*K*np.sqrt(dt)
ch = {}
for c in ['gx','gy','gz']:
    ch[c] = white_filtered(N_g) + flicker(B_g) + rw(K_g)
for c in ['ax','ay','az']:
    ch[c] = white_filtered(N_a) + flicker(B_a) + rw(K_a)
means = {'gx':0.004, 'gy':-0.003, 'gz':0.0035, 'ax':0.05, 'ay':-0.08, 'az':9.79}
# temperature profile (always present in B; written also in A as column)
Temp = 22 + 14*(1-np.exp(-t/420)) + 0.4*np.sin(2*np.pi*t/(900+50*rng.random()) + rng.random()*6)
truth = dict(style=style, seed=seed, effect=effect, fs=fs, n=n, N_g_deg_sqrth=0.25, B_g_degh=3.0,
             K_g_deghsqrth=6.0, N_a=0.05, B_a_ug=20, K_a=0.002, gm_taus=list(np.logspace(-0.5,3.2,7)))
tgt = 'gx'
if effect == 'temp':      # bias quadratic in T: ~0.02 deg/s over warm-up  (floor ~ 0.002 deg/s)
    c1 = 0.0012*rng.choice([-1,1]); c2 = 0.00004
    ch[tgt] += c1*(Temp-Temp[0]) + c2*(Temp-Temp[0])**2; truth.update(c1=c1, c2=c2)
elif effect == 'sine':
    f0 = rng.uniform(3, 0.2*fs); A0 = 0.05  # deg/s, white sd ~ 0.06-0.1
    ch[tgt] += A0*np.sin(2*np.pi*f0*t + rng.random()*6); truth.update(f0=f0, A0=A0)
elif effect == 'step':
    t0 = rng.uniform(0.3, 0.7)*T; d = 0.012*rng.choice([-1,1])
    ch[tgt] += d*(t > t0); truth.update(t0=t0, d=d)
elif effect == 'outliers':
    k = rng.choice(n, 6, replace=False); ch[tgt][k] += rng.choice([-1,1], 6)*1.5
    truth.update(idx=[int(i) for i in k])
elif effect == 'rw':
    Kx = 25*K_g; ch[tgt] += rw(Kx); truth.update(K_extra_deghsqrth=6*25)
elif effect == 'ramp':
    R = 0.03/T*rng.choice([-1,1]); ch[tgt] += R*t; truth.update(slope=R)
elif effect == 'warmup':
    A = 0.015; tau = 0.08*T; ch[tgt] += A*np.exp(-t/tau); truth.update(A=A, tau=tau)
for c in ch: ch[c] = ch[c] + means[c]
if style == 'A':
    cols = ['Time[ms]','GyroX[deg/s]','GyroY[deg/s]','GyroZ[deg/s]','AccX[g]','AccY[g]','AccZ[g]','Temp_C']
    data = [t*1000] + [ch[c] for c in ['gx','gy','gz']] + [ch[c]/9.80665 for c in ['ax','ay','az']] + [Temp]
    fmt = ['%.3f'] + ['%.7f']*3 + ['%.8f']*3 + ['%.3f']
    sep = ','; hdr = sep.join(cols)
elif style == 'B':
    # delta-angle / delta-velocity integrators, quantised cumulative sums (carry remainder)
    lsb_g = 0.0001  # deg per increment -> rate LSB 0.0125 deg/s at 125 Hz
    lsb_a = 0.00005  # m/s per increment
    outc = {}
    for c in ch:
        lsb = lsb_g if c[0]=='g' else lsb_a
        ang = np.cumsum(ch[c]*dt); q = np.round(ang/lsb)*lsb
        inc = np.diff(np.concatenate([[0.], q]))
        outc[c] = inc/dt
    truth.update(lsb_g_deg=lsb_g, lsb_a_mps=lsb_a)
    cols = ['t','gx [deg/h]','gy [deg/h]','gz [deg/h]','ax [mg]','ay [mg]','az [mg]','temp']
    data = [t] + [outc[c]*3600 for c in ['gx','gy','gz']] + [outc[c]/9.80665e-3 for c in ['ax','ay','az']] + [Temp]
    fmt = ['%.4f'] + ['%.3f']*3 + ['%.5f']*3 + ['%.3f']
    sep = ';'; hdr = sep.join(cols)
else:
    lsb_g = 0.001*np.pi/180; lsb_a = 0.002   # rad/s, m/s^2 (each sample rounded)
    cols = None
    data = [np.round(np.deg2rad(ch[c])/lsb_g)*lsb_g for c in ['gx','gy','gz']] + \
           [np.round(ch[c]/lsb_a)*lsb_a for c in ['ax','ay','az']]
    fmt = ['%.9f']*3 + ['%.4f']*3
    sep = ' '; hdr = None; truth.update(lsb_g_rad=lsb_g, lsb_a=lsb_a)
M = np.column_stack(data)
with open(out, 'w') as f:
    if hdr: f.write(hdr + '\n')
    np.savetxt(f, M, fmt=fmt, delimiter=sep)
json.dump(truth, open(out + '.truth.json', 'w'), indent=1)
