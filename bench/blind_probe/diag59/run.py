#!/usr/bin/env python3
"""Driver: fit on clean record, diagnose new records with hidden effects, --add found, held-out check.
usage: SINSIM=/path/sinsim run.py WORKDIR [--seeds 10] [--bases wgm,wrw,wfl,ar2] [--budget-min 30]
Appends one JSON line per diagnose to WORKDIR/results.jsonl (resumable: skips done keys)."""
import os, sys, json, subprocess, time, random, argparse
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gen
S = os.environ['SINSIM']
ap = argparse.ArgumentParser(); ap.add_argument('work'); ap.add_argument('--seeds', type=int, default=10)
ap.add_argument('--first-seed', type=int, default=0)
ap.add_argument('--bases', default='wgm,wrw,wfl,ar2'); ap.add_argument('--budget-min', type=float, default=30)
ap.add_argument('--holdout-seeds', type=int, default=5)
a = ap.parse_args()
W = a.work; os.makedirs(W, exist_ok=True); R = os.path.join(W, 'results.jsonl')
done = set()
if os.path.exists(R):
    for l in open(R): done.add(json.loads(l)['key'])
INCAT = ['ramp', 'sinusoid', 'bias_jumps', 'outliers', 'random_walk', 'gauss_markov', 'warmup', 'quantization']
OUTCAT = ['chirp', 'noiseburst', 'triangle', 'telegraph']
SIZES = [0.7, 2.0, 6.0]
COMBOS = [[('ramp', 3), ('sinusoid', 3)], [('bias_jumps', 3), ('random_walk', 3)],
          [('outliers', 3), ('gauss_markov', 3)], [('warmup', 3), ('sinusoid', 3)]]
t0 = time.time()

def sh(cmd, timeout=180):
    t = time.time()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        return p.returncode, p.stdout, p.stderr, time.time() - t
    except subprocess.TimeoutExpired:
        return 'timeout', '', '', time.time() - t

def summarize(js):
    out = {}
    for ax in js.get('axes', []):
        rep = [f for f in ax['findings'] if f.get('reported')]
        out[ax['channel']] = dict(found=[(f['effect'], round(f['score'], 1)) for f in rep],
                                 misfit=ax['misfit'], fits=ax.get('fits'), noise_scale=ax.get('noise_scale'),
                                 unexplained=ax.get('unexplained'), unexplained_steps=len(ax.get('unexplained_steps', []) or []),
                                 misfit_before=ax.get('misfit_before'), misfit_after=ax.get('misfit_after'),
                                 added=ax.get('added'))
    return out

def diagnose(rec, model, tag, extra=()):
    j = rec.replace('.csv', f'.{tag}.json')
    cmd = [S, 'diagnose', rec, '--rate', '100', '--model', model, '--threads', '1', '--json', j] + list(extra)
    rc, o, e, dt = sh(cmd)
    res = dict(rc=rc, dt=round(dt, 2), cmd=' '.join(cmd), stderr=e[-800:], stdout_tail=o[-1500:])
    if rc == 0 and os.path.exists(j):
        res['axes'] = summarize(json.load(open(j)))
    return res

def log(d):
    with open(R, 'a') as f: f.write(json.dumps(d) + '\n')

for s in range(a.first_seed, a.first_seed + a.seeds):
    for bi, base in enumerate(a.bases.split(',')):
        if (time.time() - t0)/60 > a.budget_min: print('budget reached'); sys.exit(0)
        d = os.path.join(W, f'{base}_s{s}'); os.makedirs(d, exist_ok=True)
        sd0 = 100000 + 1000*bi + 10*s
        clean = os.path.join(d, 'clean.csv'); model = os.path.join(d, 'model.yaml')
        if not os.path.exists(model):
            gen.make_record(clean, base, sd0)
            rc, o, e, dt = sh([S, 'fit', clean, '--rate', '100', '--threads', '1', '-o', model, '-q'])
            if rc != 0: log(dict(key=f'{base}/{s}/fit', kind='fit', base=base, seed=s, rc=rc, stderr=e[-800:])); continue
        # case list
        rnd = random.Random(sd0)
        singles = [(e_, z) for e_ in INCAT + OUTCAT for z in SIZES]; rnd.shuffle(singles)
        cases = [('null', [], [])]
        for i in range(0, len(singles), 2):
            fx = [singles[i]]; fz = [singles[i+1]] if i+1 < len(singles) else []
            cases.append((f'single{i//2}', fx, fz))
        cases.append(('combo0', COMBOS[0], COMBOS[1])); cases.append(('combo1', COMBOS[2], COMBOS[3]))
        for ci, (name, fx, fz) in enumerate(cases):
            key = f'{base}/{s}/{name}'
            if key in done: continue
            rec = os.path.join(d, f'{name}.csv')
            vis = gen.make_record(rec, base, sd0 + 1 + 100*ci, fx, fz)
            hold = any(z >= 2 for _, z in fx + fz) and s < a.first_seed + a.holdout_seeds
            imp = os.path.join(d, f'{name}.improved.yaml')
            r = diagnose(rec, model, 'diag', ['--add', 'found', '-o', imp] if name != 'null' else [])
            out = dict(key=key, kind='case', base=base, seed=s, name=name, fx=fx, fz=fz, vis=vis, diag=r)
            if hold and r.get('rc') == 0 and os.path.exists(imp):
                rec3 = os.path.join(d, f'{name}.hold.csv')
                gen.make_record(rec3, base, sd0 + 55 + 100*ci, fx, fz)
                out['hold_orig'] = diagnose(rec3, model, 'hold_orig')
                out['hold_imp'] = diagnose(rec3, imp, 'hold_imp')
                os.remove(rec3)
            log(out)
            for fn in (rec,):
                if os.path.exists(fn) and name != 'null': os.remove(fn)
        print(f'{base} s{s} done at {(time.time()-t0)/60:.1f} min', flush=True)
