#!/usr/bin/python3
"""probe.py SCENARIO N [TAG] [--model M]: run `sinsim run --seed k` for k=1..N (one at a time),
collect filter.csv + summary.json outages, and compute own consistency statistics."""
import sys, os, subprocess, json, numpy as np
from scipy.stats import chi2
BIN = os.environ.get('SINSIM', '/tmp/probe_bin27/sinsim')
scen, N = sys.argv[1], int(sys.argv[2])
tag = sys.argv[3] if len(sys.argv) > 3 else os.path.splitext(os.path.basename(scen))[0]
extra = sys.argv[4:]
base = f'runs/{tag}'
os.makedirs(base, exist_ok=True)
F, S, W = [], [], []
for k in range(1, N + 1):
    d = f'{base}/s{k}'
    if not os.path.exists(f'{d}/filter.csv'):
        p = subprocess.run([BIN, 'run', scen, '-o', d, '--seed', str(k)] + extra, capture_output=True, text=True)
        if p.returncode: print(p.stderr); sys.exit(1)
        W.append(p.stderr.strip())
    import csv
    with open(f'{d}/filter.csv') as f:
        r = csv.reader(f); hdr = next(r); rows = [[float(x) if x != '' else np.nan for x in row] for row in r]
    F.append(np.array(rows)); S.append(json.load(open(f'{d}/summary.json')))
ws = set(w for w in W if w)
if ws: print('stderr/warnings:', *ws, sep='\n  ')
A = np.stack(F)  # runs, epochs, cols
h = {n: i for i, n in enumerate(hdr)}
t = A[0, :, h['t_s']]
st = ['north_m','east_m','down_m','vn_mps','ve_mps','vd_mps','psi_n_rad','psi_e_rad','psi_d_rad']
e = A[:, :, [h[s] for s in st]]; sg = A[:, :, [h['sigma_' + s] for s in st]]
nees = A[:, :, h['nees']]; nis = A[:, :, h['nis']]; dof = A[0, :, h['nis_dof']]
out = A[0, :, h['outage']] > 0
nd = 9  # check header-based dof? vertical held -> 7
if 'held' in open(scen).read(): nd = 7
R = N
lo, hi = chi2.ppf(0.005, R * nd) / R, chi2.ppf(0.995, R * nd) / R
mn = nees.mean(0)
for cls, m in (('aiding', ~out), ('outage', out)):
    if m.sum() == 0: continue
    x = mn[m]
    print(f'NEES {cls}: epochs {m.sum()}, inside 99% band [{lo:.2f},{hi:.2f}] {np.sum((x>=lo)&(x<=hi))}/{m.sum()}, above {np.sum(x>hi)}, below {np.sum(x<lo)}; mean {x.mean():.2f} (dof {nd}); median {np.median(x):.2f} max {x.max():.2f}')
m = ~out & (dof > 0)
if m.any():
    d0 = int(dof[m][0]); nl, nh = chi2.ppf(0.005, R*d0)/R, chi2.ppf(0.995, R*d0)/R
    x = np.nanmean(nis[:, m], 0)
    print(f'NIS: dof {d0}, epochs {m.sum()}, inside [{nl:.2f},{nh:.2f}] {np.sum((x>=nl)&(x<=nh))}/{m.sum()}, mean {x.mean():.3f}')
# per-state coverage
z = np.abs(e / sg)
print('per-state coverage (all epochs x runs) within 1/2/3 sigma (expect 68.3/95.4/99.7 %), mean z^2:')
for i, s in enumerate(st):
    for cls, mm in (('aid', ~out), ('out', out)):
        if mm.sum() == 0: continue
        zz = z[:, mm, i].ravel(); n = zz.size
        print(f'  {s:9s} {cls}: ' + ' '.join(f'{np.sum(zz<=k)}/{n}={100*np.mean(zz<=k):.1f}%' for k in (1,2,3)) + f'  mean z2 {np.mean(zz**2):.2f}')
# outage horizontal: max error vs filter sigma (summary.json), and per-epoch 2D test
print('outages (summary.json): max horizontal / filter sigma_h ; own: share of runs with max <= 1,2,3 sigma_h (2-D equal-axis expectation 63/98/100 % for a point; for the max over a window lower)')
for j, o in enumerate(S[0].get('outages') or []):
    mx = np.array([s['outages'][j]['max_horizontal_m'] if s['outages'][j]['max_horizontal_m'] is not None else np.nan for s in S])
    sh = np.array([s['outages'][j]['filter_sigma_horizontal_m'] if s['outages'][j]['filter_sigma_horizontal_m'] is not None else np.nan for s in S])
    r = mx / sh
    print(f"  [{o['start_s']},{o['end_s']}): max p50 {np.nanmedian(mx):.2f} m p95 {np.nanpercentile(mx,95):.2f}, sigma_h p50 {np.nanmedian(sh):.2f}; ratio<=1: {np.sum(r<=1)}/{N}, <=2: {np.sum(r<=2)}/{N}, <=3: {np.sum(r<=3)}/{N}")
    # per-epoch inside the window: 2-D horizontal NEES using N,E sigmas (diagonal only)
    mm = out & (t >= o['start_s']) & (t <= o['end_s'] + 1e-9)
    if mm.any():
        eh = np.hypot(e[:, mm, 0], e[:, mm, 1]); sh2 = np.hypot(sg[:, mm, 0], sg[:, mm, 1])
        rr = (eh / sh2).ravel()
        print(f"     per outage epoch |e_h|/sigma_h <=1: {np.sum(rr<=1)}/{rr.size}={100*np.mean(rr<=1):.1f}% (exp ~63%), <=2: {np.sum(rr<=2)}/{rr.size}={100*np.mean(rr<=2):.1f}% (exp ~98%)")
        ee = e[:, mm, :2]; ss = sg[:, mm, :2]
        q = ((ee/ss)**2).sum(-1).mean(0)
        print(f"     run-avg diag 2-D NEES at end of window {q[-1]:.2f} (expect 2), max over window {q.max():.2f}")
np.savez(f'{base}/stats.npz', t=t, nees_mean=mn, out=out, e=e, sg=sg, nis=nis)
print('yaw sigma (deg) at selected times run 1:', [(float(t[i]), round(float(np.degrees(sg[0,i,8])),3)) for i in np.linspace(0, len(t)-1, 8).astype(int)])
