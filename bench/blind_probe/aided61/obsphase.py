#!/usr/bin/python3
"""obsphase.py TAG: per phase of obs.yaml: tilt/yaw error and sigma, yaw-error slope (= residual gyro-z bias)"""
import sys, numpy as np
d = np.load(f'runs/{sys.argv[1]}/stats.npz'); t, e, sg = d['t'], d['e'], d['sg']
ph = [(0,600,'static'),(630,1220,'straight 20 m/s'),(1220,1240,'turn +90'),(1250,1540,'straight'),(1540,1580,'turn -90+accel'),(1590,2400,'straight 30 m/s'),(2400,2480,'outage')]
D = np.degrees
for a, b, n in ph:
    m = (t >= a) & (t < b); i0, i1 = np.where(m)[0][[0, -1]]
    sl = np.array([np.polyfit(t[m], e[r, m, 8], 1)[0] for r in range(e.shape[0])])  # rad/s
    print(f'{n:16s} {a}-{b}: end: yaw err rms {D(np.sqrt((e[:,i1,8]**2).mean())):.3f} deg sigma {D(sg[0,i1,8]):.3f} (start sigma {D(sg[0,i0,8]):.3f}); '
          f'tilt N/E err rms {1e3*np.sqrt((e[:,i1,6]**2).mean()):.3f}/{1e3*np.sqrt((e[:,i1,7]**2).mean()):.3f} mrad sigma {1e3*sg[0,i1,6]:.3f}/{1e3*sg[0,i1,7]:.3f}; '
          f'psi_d slope mean {D(sl.mean())*3600:.2f} deg/h (sd {D(sl.std())*3600:.2f})')
