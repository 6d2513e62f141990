#!/usr/bin/env python3
"""Tables from WORKDIR/results.jsonl.  usage: analyze.py WORKDIR"""
import json, sys, collections
R = [json.loads(l) for l in open(sys.argv[1] + '/results.jsonl')]
INCAT = ['ramp', 'sinusoid', 'bias_jumps', 'outliers', 'random_walk', 'gauss_markov', 'warmup', 'quantization']
OUTCAT = ['chirp', 'noiseburst', 'triangle', 'telegraph']
bad = [r for r in R if r.get('kind') == 'fit' or r['diag'].get('rc') != 0]
print('## runs', len(R), 'failed', len(bad))
for r in bad: print('  FAILED', r['key'], r.get('diag', r).get('rc'), r.get('diag', r).get('stderr', '')[-300:])
cases = [r for r in R if r.get('kind') == 'case' and r['diag'].get('rc') == 0]
bases = sorted(set(r['base'] for r in cases))
print('\n## 1. false alarms on clean channels (any reported finding) / unexplained flags')
print('| base | null records (gx,gy,gz) | gy of effect records | unexplained (tau range or steps) on all clean channels | what was named |')
print('|---|---|---|---|---|')
for b in bases:
    n1 = k1 = n2 = k2 = u = 0; named = collections.Counter()
    for r in cases:
        if r['base'] != b: continue
        chs = ['gx', 'gy', 'gz'] if r['name'] == 'null' else ['gy']
        for c in chs:
            a = r['diag']['axes'][c]
            hit = bool(a['found'])
            if r['name'] == 'null': n1 += 1; k1 += hit
            else: n2 += 1; k2 += hit
            u += bool(a['unexplained']) or a['unexplained_steps'] > 0
            for e, s in a['found']: named[e] += 1
    print(f'| {b} | {k1}/{n1} | {k2}/{n2} | {u}/{n1+n2} | {dict(named)} |')

def chan_truth(r):
    out = []
    if r['fx']: out.append(('gx', r['fx']))
    if r['fz']: out.append(('gz', r['fz']))
    return out

print('\n## 2. single effects: first reported finding == truth (k/n), truth anywhere in reported, nothing reported; by target ADEV visibility')
tab = collections.defaultdict(lambda: collections.Counter()); wrong = collections.defaultdict(collections.Counter)
for r in cases:
    if not r['name'].startswith('single'): continue
    for c, spec in chan_truth(r):
        (e, z), = spec
        a = r['diag']['axes'][c]; f = [x[0] for x in a['found']]
        t = tab[(e, z)]; t['n'] += 1
        t['first'] += bool(f) and f[0] == e; t['any'] += e in f; t['none'] += not f
        t['unexpl'] += (not f) and (bool(a['unexplained']) or a['unexplained_steps'] > 0)
        if f and f[0] != e: wrong[(e, z)]['+'.join(f)] += 1
        if not f: wrong[(e, z)]['(nothing%s)' % (', unexplained' if (a['unexplained'] or a['unexplained_steps']) else '')] += 1
        t['vis'] += 0
print('| effect | size (ADEV x base) | right first | right anywhere | nothing reported | nothing but flagged unexplained | what else was said |')
print('|---|---|---|---|---|---|---|')
for e in INCAT + OUTCAT:
    for z in (0.7, 2.0, 6.0):
        t = tab.get((e, z))
        if not t: continue
        n = t['n']
        print(f"| {e}{' (out of catalogue)' if e in OUTCAT else ''} | {z} | {t['first']}/{n} | {t['any']}/{n} | {t['none']}/{n} | {t['unexpl']}/{n} | {dict(wrong[(e, z)])} |")

print('\n## 3. two-effect channels (each 3x)')
ct = collections.defaultdict(collections.Counter)
for r in cases:
    if not r['name'].startswith('combo'): continue
    for c, spec in chan_truth(r):
        tr = [e for e, _ in spec]; f = [x[0] for x in r['diag']['axes'][c]['found']]
        k = sum(e in f for e in tr); extra = [e for e in f if e not in tr]
        t = ct['+'.join(tr)]; t['n'] += 1; t['both' if k == 2 else 'one' if k == 1 else 'none'] += 1; t['extra'] += bool(extra)
        if extra: t['extra:' + '+'.join(extra)] += 1
print('| pair | n | both named | one | none | with a wrong extra | extras |')
print('|---|---|---|---|---|---|---|')
for p, t in ct.items():
    ex = {k[6:]: v for k, v in t.items() if k.startswith('extra:')}
    print(f"| {p} | {t['n']} | {t['both']}/{t['n']} | {t['one']}/{t['n']} | {t['none']}/{t['n']} | {t['extra']}/{t['n']} | {ex} |")

print('\n## 4. --add found: misfit before->after on the record, and on a held-out record (same physics, new seed): original model vs improved')
at = collections.defaultdict(collections.Counter); rows = []
for r in cases:
    if r['name'] == 'null': continue
    for c, spec in chan_truth(r):
        a = r['diag']['axes'][c]
        if not a['found']: continue
        cat = 'in' if all(e in INCAT for e, _ in spec) else 'out'
        right = all(e in [x[0] for x in a['found']] for e, _ in spec)
        key = (cat, 'right' if right else 'wrong')
        t = at[key]; t['n'] += 1
        mb, ma = a['misfit_before'], a['misfit_after']
        if mb is not None and ma is not None:
            t['halved'] += ma <= 0.5*mb; t['rose'] += ma > mb + 1e-9
        if 'hold_orig' in r and r['hold_orig'].get('rc') == 0 and r['hold_imp'].get('rc') == 0:
            ho, hi = r['hold_orig']['axes'][c], r['hold_imp']['axes'][c]
            t['hn'] += 1; t['h_lower'] += hi['misfit'] < ho['misfit'] - 1e-9; t['h_halved'] += hi['misfit'] <= 0.5*ho['misfit']
            t['h_clean'] += not hi['found']; t['h_worse'] += hi['misfit'] > ho['misfit'] + 1e-9
            rows.append((r['key'], c, spec, [x[0] for x in a['found']], round(mb, 3), round(ma, 3), round(ho['misfit'], 3), round(hi['misfit'], 3), hi['found']))
print('| effect class | named right? | n | misfit halved on record | misfit rose on record | held-out n | held-out misfit lower with improved | halved | improved model: nothing more named on held-out | held-out worse |')
print('|---|---|---|---|---|---|---|---|---|---|')
for k, t in sorted(at.items()):
    print(f"| {k[0]} | {k[1]} | {t['n']} | {t['halved']}/{t['n']} | {t['rose']}/{t['n']} | {t['hn']} | {t['h_lower']}/{t['hn']} | {t['h_halved']}/{t['hn']} | {t['h_clean']}/{t['hn']} | {t['h_worse']}/{t['hn']} |")
print('\nheld-out rows where the improved model still had findings or misfit not lower:')
for x in rows:
    if x[8] or not x[7] < x[6]: print('  ', x)
print('\n## timing: max diagnose wall', max(r['diag']['dt'] for r in cases), 's; median', sorted(r['diag']['dt'] for r in cases)[len(cases)//2])
