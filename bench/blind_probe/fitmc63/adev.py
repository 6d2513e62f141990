#!/usr/bin/python3
"""Own overlapping ADEV of a record (octave taus) + truth theory; optional compare with sinsim analyze JSON.
usage: adev.py REC.csv SENSOR [analyze.json]"""
import sys, json, numpy as np
sys.path.insert(0, '/tmp/probe_63/work/scripts')
from gen import SENSORS
def oadev(y, dt, ms):
    x = np.concatenate([[0], np.cumsum(y)])*dt
    out = []
    for m in ms:
        d = x[2*m:] - 2*x[m:-m] + x[:-2*m]
        out.append(np.sqrt(np.mean(d**2)/(2*(m*dt)**2)))
    return np.array(out)
def theory(p, tau, dt):
    v = p['N']**2/tau
    for s, tc in p.get('gm', []):
        r = tau/tc
        v += s**2*(tc/tau)**2*(2*r - 3 + 4*np.exp(-r) - np.exp(-2*r))
    if 'K' in p: v += p['K']**2*tau/3
    if 'B' in p: v += (0.664*p['B']/np.sqrt(2))**2*np.ones_like(tau)
    if 'lsb' in p: v += p['lsb']**2/12*dt/tau
    return np.sqrt(v)
if __name__ == '__main__':
    rec, S = sys.argv[1], sys.argv[2]
    A = np.loadtxt(rec, delimiter=',', skiprows=1)
    dt = A[1,0]-A[0,0]; n = len(A)
    ms = 2**np.arange(0, int(np.log2(n/4)) + 1)
    tau = ms*dt
    aj = json.load(open(sys.argv[3])) if len(sys.argv) > 3 else None
    names = ['gx','gy','gz','ax','ay','az']
    for i, nm in enumerate(names):
        y = A[:, i+1]
        ad = oadev(y, dt, ms); th = theory(SENSORS[S]['gyro' if i < 3 else 'accel'], tau, dt)
        print(f"{nm}: tau  own_adev  truth_theory  own/theory" + ("  sinsim/own" if aj else ""))
        sj = None
        if aj:
            # find this channel's allan curve in the JSON (structure probed loosely)
            al = aj['channels'][nm]['allan']; st = np.array(al['tau_s']); sd = np.array(al['adev'])
        for j in range(len(tau)):
            line = f"  {tau[j]:9.2f} {ad[j]:.4e} {th[j]:.4e} {ad[j]/th[j]:6.3f}"
            if aj:
                k = np.argmin(abs(st - tau[j]))
                if abs(st[k]-tau[j]) < 1e-6*tau[j]: line += f"  {sd[k]/ad[j]:.6f}"
            print(line)
