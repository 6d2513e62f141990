"""Recompute summary.json budget shares and SEs from per_run.csv; compare to closed forms for budget5.yaml on static120.
usage: check_budget.py OUTDIR"""
import sys, csv, json, numpy as np
d = sys.argv[1]; js = json.load(open(f'{d}/summary.json'))
h = {}
for r in csv.DictReader(open(f'{d}/per_run.csv')):
    h.setdefault((r['model'], float(r['t [s]'])), []).append(float(r['horizontal [m]']))
g = 9.8062
def closed(t):
    ax = 0.02**2*t**3/3; ay = 0.01**2*t**3/3; gx = g**2*1e-8*t**5/20; gy = g**2*0.25e-8*t**5/20
    return {'gyro.x[0].white': gx, 'gyro.y[0].white': gy, 'gyro.z[0].bias': 0.0, 'accel.x[0].white': ax, 'accel.y[0].white': ay}
for b in js['budget']:
    m = b['model']
    for a in b['at']:
        t = a['t_s']; full = np.array(h[(m, t)])**2; msf = full.mean(); cf = closed(t); tot = sum(cf.values())
        print(f"t={t}: ms_full json {a['ms_full_m2']:.6g} recomputed {msf:.6g}; closed-form total {tot:.6g}; sum_of_shares {a['sum_of_shares']:.4f}")
        for e in a['effects']:
            wo = np.array(h[(f'{m} without {e["effect"]}', t)])**2
            dd = full - wo; share = dd.mean()/msf; se = dd.std(ddof=1)/np.sqrt(len(dd))/msf
            z = (e['share'] - cf[e['effect']]/tot)/e['share_se']
            print(f"   {e['effect']:18s} share {e['share']:.4f} (recomp {share:.4f}) se {e['share_se']:.4f} (recomp {se:.4f}) closed {cf[e['effect']]/tot:.4f} z={z:+.2f}")
