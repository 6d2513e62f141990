#!/usr/bin/python3
"""Compare sinsim run errors.csv with closed forms. usage: closed_form.py acc|gyro errors.csv"""
import sys, numpy as np
kind, fn = sys.argv[1], sys.argv[2]
A = np.genfromtxt(fn, delimiter=',', names=True)
names = A.dtype.names
t = A[names[0]]; N = A[names[1]]; E = A[names[2]]
lat = np.radians(45); W = 7.292115e-5
a, f = 6378137.0, 1/298.257223563; e2 = f*(2-f)
M = a*(1-e2)/(1-e2*np.sin(lat)**2)**1.5; Rn = a/np.sqrt(1-e2*np.sin(lat)**2)
g = 9.7803253359*(1+0.00193185265241*np.sin(lat)**2)/np.sqrt(1-e2*np.sin(lat)**2)
ws2 = g/M; wf = W*np.sin(lat); w = np.sqrt(ws2+wf**2)
if kind == 'acc':
    b = 100e-6*9.80665
    z = (b/ws2)*(1 - np.exp(1j*wf*t)*(np.cos(w*t) - 1j*(wf/w)*np.sin(w*t)))
    cfN, cfE = z.real, -z.imag   # try both signs for E, report the better
    short = 0.5*b*t**2
    print("t[s]  sim_N  closed_N  sim_E  closed_E(+/-)  0.5bt^2")
    for tt in [30, 60, 120, 300, 600, 1200, 2400, 3600, 5400]:
        i = np.argmin(abs(t-tt))
        print(f"{t[i]:6.0f} {N[i]:10.3f} {cfN[i]:10.3f} {E[i]:9.3f} {z.imag[i]:9.3f} {short[i]:10.3f}")
    pk = np.max(abs(z))
    print("worst |sim-closed| (E sign +):", np.max(np.hypot(N-cfN, E-z.imag)), "(E sign -):", np.max(np.hypot(N-cfN, E+z.imag)), "peak", pk)
else:
    eps = np.radians(1)/3600
    short = g*eps*t**3/6
    sch = M*eps*(t - np.sin(np.sqrt(ws2)*t)/np.sqrt(ws2))
    print("t[s]  sim_N  sim_E  g*eps*t^3/6  R*eps*(t-sin(ws t)/ws)  ratio sim|N|/schuler")
    for tt in [30, 60, 120, 300, 600, 1200, 2400, 3600, 5400]:
        i = np.argmin(abs(t-tt))
        print(f"{t[i]:6.0f} {N[i]:10.3f} {E[i]:9.3f} {short[i]:10.3f} {sch[i]:10.3f} {abs(N[i])/sch[i]:7.4f}")
