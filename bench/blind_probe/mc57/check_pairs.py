"""Recompute summary.json comparisons (paired t, CI, Wilcoxon) from per_run.csv. usage: check_pairs.py OUTDIR"""
import sys, csv, json, numpy as np
from scipy import stats as S
d = sys.argv[1]
js = json.load(open(f'{d}/summary.json'))
h = {}
for r in csv.DictReader(open(f'{d}/per_run.csv')):
    h.setdefault((r['model'], float(r['t [s]'])), []).append(float(r['horizontal [m]']))
worst = {}
def cmp(name, got, exp, tol=1e-6):
    if exp is None or (isinstance(exp,float) and np.isnan(exp)):
        print(f'  {name}: got {got} expected {exp}'); return
    rel = abs(got-exp)/max(abs(exp),1e-300) if exp != 0 else abs(got)
    worst[name] = max(worst.get(name,0), rel)
    if rel > tol: print(f'  MISMATCH {name}: got {got!r} recomputed {exp!r} rel {rel:.2e}')
for c in js['comparisons']:
    for a in c['at']:
        A = np.array(h[(c['a'], a['t_s'])]); Bv = np.array(h[(c['b'], a['t_s'])]); dd = A - Bv; n = len(dd)
        cmp('mean_a', a['mean_a_m'], A.mean()); cmp('mean_b', a['mean_b_m'], Bv.mean())
        cmp('mean_diff', a['mean_difference_m'], dd.mean(), 1e-5)
        cmp('sd_diff', a['sd_difference_m'], dd.std(ddof=1), 1e-5)
        if dd.std() > 0:
            t = S.ttest_rel(A, Bv); cmp('t', a['t'], t.statistic, 1e-4); cmp('p_t', a['p_t'], t.pvalue, 1e-3)
            ci = S.t.ppf(0.975, n-1)*dd.std(ddof=1)/np.sqrt(n)
            cmp('ci_lo', a['ci95_difference_m'][0], dd.mean()-ci, 1e-4); cmp('ci_hi', a['ci95_difference_m'][1], dd.mean()+ci, 1e-4)
        nz = dd[dd != 0]
        if len(nz):
            exact = a.get('wilcoxon_exact')
            w = S.wilcoxon(A, Bv, zero_method='wilcox', correction=not exact, method='exact' if exact else 'approx')
            r = S.rankdata(np.abs(nz)); wp = r[nz > 0].sum()
            cmp('w_plus', a['wilcoxon_w_plus'], wp); cmp('p_wilcoxon', a['p_wilcoxon'], w.pvalue, 1e-3)
            cmp('wilcoxon_n', a['wilcoxon_n'], len(nz))
        else:
            print(f"  all differences zero at t={a['t_s']}: json {json.dumps(a)}")
print('worst rel diffs:', {k: f'{v:.1e}' for k,v in worst.items()})
