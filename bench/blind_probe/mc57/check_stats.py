"""Recompute stats.csv (at the per_run times) and summary.json CEP/R95 from per_run.csv; report max rel diff.
usage: check_stats.py OUTDIR"""
import sys, csv, json, numpy as np
d = sys.argv[1]
rows = list(csv.reader(open(f'{d}/per_run.csv')))
hdr = rows[0]; data = rows[1:]
cols = {h:i for i,h in enumerate(hdr)}
from collections import defaultdict
g = defaultdict(list)
for r in data: g[(r[0], float(r[2]))].append(r)
st = list(csv.DictReader(open(f'{d}/stats.csv')))
stk = {(r['model'], float(r['t_s'])): r for r in st}
qmap = {'horizontal_m':'horizontal [m]','vertical_m':'vertical [m]'}
worst = 0; nchk = 0
for (m,t), rs in sorted(g.items()):
    runs = [int(r[1]) for r in rs]
    assert runs == sorted(runs), (m,t)
    if (m,t) not in stk: print('missing stats row', m, t); continue
    S = stk[(m,t)]
    arr = {h: np.array([float(r[cols[h]]) for r in rs]) for h in hdr[3:]}
    der = {'horizontal_m': arr['horizontal [m]'], 'vertical_m': np.abs(arr['down [m]']),
           'velocity_mps': np.sqrt(arr['vn [m/s]']**2+arr['ve [m/s]']**2+arr['vd [m/s]']**2),
           'roll_abs_rad': np.abs(arr['roll [rad]']), 'pitch_abs_rad': np.abs(arr['pitch [rad]']), 'yaw_abs_rad': np.abs(arr['yaw [rad]'])}
    for q, x in der.items():
        exp = {'mean': x.mean(), 'sd': x.std(ddof=1), 'rms': np.sqrt((x**2).mean()),
               'p50': np.percentile(x,50), 'p68': np.percentile(x,68), 'p95': np.percentile(x,95), 'p99': np.percentile(x,99)}
        for k,v in exp.items():
            got = float(S[f'{q}_{k}']); nchk += 1
            rel = abs(got-v)/max(abs(v),1e-300) if v!=0 else abs(got)
            if rel > 1e-5 and abs(got-v) > 1e-12:
                print(f'MISMATCH {m} t={t} {q}_{k}: stats {got:.9g} vs per_run {v:.9g} rel {rel:.2e}')
            worst = max(worst, rel if abs(got-v)>1e-12 else 0)
    sg = {'north_m':'north [m]','east_m':'east [m]','down_m':'down [m]','vn_mps':'vn [m/s]','ve_mps':'ve [m/s]','vd_mps':'vd [m/s]','roll_rad':'roll [rad]','pitch_rad':'pitch [rad]','yaw_rad':'yaw [rad]'}
    for q,h in sg.items():
        x = arr[h]
        for k,v in (('mean',x.mean()),('sd',x.std(ddof=1))):
            got = float(S[f'{q}_{k}']); nchk += 1
            rel = abs(got-v)/max(abs(v),1e-300) if v!=0 else abs(got)
            if rel > 1e-5 and abs(got-v) > 1e-9*max(1,x.std()):
                print(f'MISMATCH {m} t={t} {q}_{k}: stats {got:.9g} vs per_run {v:.9g} rel {rel:.2e}')
print(f'checked {nchk} stats values, worst rel diff {worst:.2e}')
