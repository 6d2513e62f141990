#!/usr/bin/python3
"""Run analyze/fit/diagnose on every variant; compare with the reference; write results.json + table."""
import json, subprocess, os, sys, re, glob, shutil
B = '/tmp/probe_bin58/sinsim'
V = json.load(open('variants.json'))
only = sys.argv[1:]
OUT = 'out'; os.makedirs(OUT, exist_ok=True)
def run(cmd, timeout=170):
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, errors='replace')
        return p.returncode, p.stdout, p.stderr
    except subprocess.TimeoutExpired:
        return 'TIMEOUT', '', ''
def stats(js):
    d = json.load(open(js)); r = {'samples': d['samples'], 'rate': d['rate_hz']}
    for c, v in d['channels'].items():
        r[c + '.mean'] = v['mean']; r[c + '.std'] = v['std']
        for t, a in zip(v['allan']['tau_s'], v['allan']['adev']): r['%s.adev@%.6g' % (c, t)] = a
    return r
def cmp(a, b):
    if set(a) != set(b): return 'KEYS differ: %s' % sorted(set(a) ^ set(b))[:6], 1.0
    worst, wk = 0.0, ''
    for k in a:
        x, y = a[k], b[k]
        rd = abs(x - y) / max(abs(y), 1e-300)
        if rd > worst: worst, wk = rd, k
    return wk, worst
def modeltext(p):
    return [l for l in open(p) if not l.lstrip().startswith('#') and not l.startswith('description')]
def diagtext(s):
    return [l for l in s.splitlines() if not l.startswith('diagnosis of') and 'wall' not in l]
refs = {}
res = []
for v in V:
    if only and v['name'] not in only: continue
    n = v['name']; d = os.path.join(OUT, n); shutil.rmtree(d, ignore_errors=True); os.makedirs(d)
    r = dict(v)
    cmd = [B, 'analyze', v['file'], '--json', d + '/a.json'] + v['args']
    r['analyze_cmd'] = ' '.join("'%s'" % c if (' ' in c or c == '') else c for c in cmd)
    rc, so, se = run(cmd); r['a_rc'] = rc; r['a_err'] = se.strip()[-1500:]; r['a_out'] = so.strip()[:3000]
    left = sorted(os.listdir(d)); r['a_files'] = left
    if rc == 0:
        s = stats(d + '/a.json'); r['a_samples'] = s['samples']; r['a_rate'] = s['rate']
        refname = 'q_ref' if n.startswith('q_') else 'ref'
        if n == refname: refs[n] = s
        if refname in refs:
            r['a_cmp'] = cmp(s, refs[refname])
        # fit
        cmd = [B, 'fit', v['file'], '--kind', 'gm', '--axes', 'gx,az', '-q', '-o', d + '/m.yaml'] + v['args']
        rc2, so2, se2 = run(cmd); r['f_rc'] = rc2; r['f_err'] = se2.strip()[-800:]
        if rc2 == 0:
            mt = modeltext(d + '/m.yaml')
            if n == refname: refs[n + '.fit'] = mt
            r['f_same'] = (mt == refs.get(refname + '.fit'))
            if not r['f_same']: r['f_model'] = ''.join(mt)
        cmd = [B, 'diagnose', v['file'], '--model', 'fit_ref.yaml', '--channels', 'gx,az', '--realisations', '8', '--seed', '1', '--json', d + '/d.json'] + v['args']
        rc3, so3, se3 = run(cmd); r['d_rc'] = rc3; r['d_err'] = se3.strip()[-800:]
        if rc3 == 0:
            dt = diagtext(so3)
            if n == refname: refs[n + '.diag'] = dt
            r['d_same'] = (dt == refs.get(refname + '.diag'))
            if not r['d_same']: r['d_out'] = '\n'.join(dt)
    else:
        # fit on refusal must also refuse & leave nothing
        cmd = [B, 'fit', v['file'], '--kind', 'gm', '--axes', 'gx,az', '-q', '-o', d + '/m.yaml'] + v['args']
        rc2, so2, se2 = run(cmd); r['f_rc'] = rc2; r['f_err'] = se2.strip()[-800:]
        cmd = [B, 'diagnose', v['file'], '--model', 'fit_ref.yaml', '--channels', 'gx,az', '--realisations', '8', '--json', d + '/d.json', '-o', d + '/imp.yaml'] + v['args']
        rc3, so3, se3 = run(cmd); r['d_rc'] = rc3; r['d_err'] = se3.strip()[-800:]
        r['left_after_refusal'] = sorted(os.listdir(d))
    res.append(r)
    c = r.get('a_cmp', ('', ''))
    print('%-32s a=%s f=%s d=%s  %s %s  fit=%s diag=%s | %s' % (n, r['a_rc'], r.get('f_rc'), r.get('d_rc'), c[0], ('%.2e' % c[1]) if c[1] != '' else '', r.get('f_same'), r.get('d_same'), (r['a_err'].splitlines() or [''])[-1][:300]), flush=True)
fn = 'results.json' if not only else 'results_partial.json'
json.dump(res, open(fn, 'w'), indent=1)
