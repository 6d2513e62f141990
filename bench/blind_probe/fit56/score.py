#!/usr/bin/python3
"""score.py CASE SEEDS KIND : compare fitted model files with truth."""
import sys, re, json, numpy as np
D2R = np.pi/180; G = 9.80665
U = {'deg/s': D2R, 'deg/h': D2R/3600, 'deg/sqrt(h)': D2R/60, 'deg/s/sqrt(Hz)': D2R, 'deg/h/sqrt(h)': D2R/3600/60,
     'deg/h^2': D2R/3600/3600, 'deg': D2R, 'rad': 1, 'mg': G*1e-3, 'ug': G*1e-6, 'g': G, 'm/s/sqrt(h)': 1/60.,
     'm/s^2/sqrt(h)': 1/60., 'm/s^3': 1., 'm/s': 1., 'm/s^2': 1., 's': 1., 'ms': 1e-3, 'min': 60., 'h': 3600., 'Hz': 1., 'mg/h': G*1e-3/3600,
     'deg/s^2': D2R, 'rad/s': 1., 'deg/h/h': D2R/3600/3600}
def q(s):
    s = s.strip(); m = re.match(r'([-+0-9.eE]+)\s*(.*)$', s)
    v = float(m.group(1)); u = m.group(2).strip()
    if u.count('(') > u.count(')'): u += ')'
    if u == '': return v
    if u not in U: print('UNKNOWN UNIT', repr(u), file=sys.stderr); return float('nan')
    return v*U[u]
def parse(path):
    out = {}; sensor = None; axis = None; pend = []
    for line in open(path):
        if re.match(r'^(gyro|accel):', line): sensor = line[0]; continue
        m = re.match(r'^  (x|y|z|all|triad):', line)
        if m: axis = m.group(1); pend = []; continue
        st = line.strip()
        if st.startswith('#'): pend.append(st); continue
        m = re.match(r'^- \{type: (\w+), (.*)\}$', st)
        if m and sensor:
            ch = sensor + axis; typ = m.group(1)
            params = {}
            for kv in re.findall(r'(\w+): (\[[^\]]*\]|[^,]+)', m.group(2)):
                params[kv[0]] = kv[1]
            e = {'type': typ, 'p': params, 'c': list(pend)}
            out.setdefault(ch, []).append(e); pend = []
    return out
def ln_of(comments, key=None):
    for c in reversed(comments):
        if '+-' not in c: continue
        segs = re.split(r'\), (?=\w+ \+-)', c)
        for sg in segs:
            if key and not re.search(r'\b' + key + r' \+-', sg): continue
            m = re.search(r'(?:ln-space|profile-likelihood 1-sigma interval) (.+?)\.\.(.+?)\)?$', sg.strip())
            if m:
                try: return (q(m.group(1)), q(m.group(2).rstrip(')')))
                except Exception: return None
        return None
    return None
def sig_of(comments, key=None):
    # returns 1-sigma in SI from the last comment line
    for c in reversed(comments):
        if key:
            m = re.search(key + r' \+- ([-+0-9.eE]+ [^ ,]+)', c)
        else:
            m = re.search(r'\+- ([-+0-9.eE]+ [^ ,]+)', c)
        if m: return q(m.group(1))
    return float('nan')
def fitted(path):
    res = {}
    for ch, effs in parse(path).items():
        d = {'set': []}; ngm = 0
        for e in effs:
            t = e['type']; p = e['p']
            if t == 'white':
                d['set'].append('white'); d['white_density'] = (q(p['density']), sig_of(e['c']), ln_of(e['c']))
            elif t == 'gauss_markov':
                ngm += 1; d['set'].append('gm')
                d[f'gm{ngm}_sigma'] = (q(p['sigma']), sig_of(e['c'], 'sigma'), ln_of(e['c'], 'sigma'))
                d[f'gm{ngm}_tau'] = (q(p['tau']), sig_of(e['c'], 'tau'), ln_of(e['c'], 'tau'))
            elif t == 'random_walk':
                d['set'].append('rw'); d['rw_K'] = (q(p['K']), sig_of(e['c']), ln_of(e['c']))
            elif t == 'bias_instability':
                d['set'].append('flicker'); k = 'B' if 'B' in p else 'floor'
                v = q(p[k]); s = sig_of(e['c'])
                if k == 'floor': v /= 0.664; s /= 0.664
                d['flicker_B'] = (v, s, None); d['flicker_raw'] = (k, p[k], e['c'][-1] if e['c'] else '')
            elif t == 'quantization':
                d['set'].append('quant'); d['quant_lsb_increment'] = (q(p['lsb']), sig_of(e['c']), ln_of(e['c']))
            elif t == 'ramp':
                d['set'].append('drift'); d['ramp_slope'] = (q(p['slope']), sig_of(e['c']), ln_of(e['c']))
            else:
                d['set'].append(t)
        if 'gm1_tau' in d and 'gm2_tau' in d and d['gm1_tau'][0] > d['gm2_tau'][0]:
            d['gm1_tau'], d['gm2_tau'] = d['gm2_tau'], d['gm1_tau']; d['gm1_sigma'], d['gm2_sigma'] = d['gm2_sigma'], d['gm1_sigma']
        if ngm == 1 and 'gm_sigma' not in d:
            d['gm_sigma'] = d.pop('gm1_sigma'); d['gm_tau'] = d.pop('gm1_tau')
        res[ch] = d
    return res
TSET = {'gm_sigma': 'gm', 'gm1_sigma': 'gm', 'gm2_sigma': 'gm', 'rw_K': 'rw', 'flicker_B': 'flicker', 'quant_lsb_increment': 'quant', 'ramp_slope': 'drift', 'white_density': 'white'}
def main():
    case, seeds, kind = sys.argv[1], sys.argv[2].split(','), sys.argv[3]
    verbose = len(sys.argv) > 4
    right = 0; tot = 0; cov = {}; sets = {}
    for s in seeds:
        base = f'{case}_{s}'
        try: tr = json.load(open(base + '.csv.truth.json'))['truth']; fr = fitted(f'{base}.{kind}.yaml')
        except Exception as ex: print(base, 'ERR', ex); continue
        for ch in ['gx', 'gy', 'gz', 'ax', 'ay', 'az']:
            t = dict(tr[ch]); f = fr.get(ch, {'set': []})
            if 'flicker_B' in t: t['flicker_B'] /= np.sqrt(2)  # my generator's one-sided PSD B^2/(2 pi f): ADEV floor 0.470 B
            tset = sorted(set(TSET[k] for k in t if k in TSET))
            fset = sorted(f['set']); tset_full = sorted([TSET[k] for k in t if k in TSET and not k.endswith('_tau')])
            ok = fset == tset_full; right += ok; tot += 1
            sets['+'.join(fset)] = sets.get('+'.join(fset), 0) + 1
            line = f'{base} {ch} set={"+".join(fset)} {"OK" if ok else "WRONG"}'
            for k, tv in t.items():
                if k == 'quant_Q': continue
                if k in f:
                    v, sg, li = f[k]; z = (v - tv)/sg if sg == sg and sg > 0 else float('nan')
                    inln = False
                    if li and v > 0 and tv > 0 and li[0] > 0:
                        lo = np.log(v) - 2*(np.log(v) - np.log(li[0])); hi = np.log(v) + 2*(np.log(li[1]) - np.log(v))
                        inln = lo <= np.log(tv) <= hi
                    if ok:
                        c = cov.setdefault(k, [0, 0, [], 0]); c[1] += 1; c[0] += abs(z) <= 2; c[2].append(v/tv); c[3] += (abs(z) <= 2) or inln
                    line += f' {k}: {v:.4g}/{tv:.4g} (r {v/tv:.3f}, z {z:+.2f}{", ln-in" if inln else ""})'
                else:
                    line += f' {k}: MISSING'
            if verbose: print(line)
    print(f'== {case} {kind}: right set {right}/{tot}; sets seen {sets}')
    for k, (a, b, r, u) in cov.items():
        print(f'   {k}: |z|<=2 {a}/{b}; union(lin or ln/profile) {u}/{b}; median est/true {np.median(r):.3f}')
main()
