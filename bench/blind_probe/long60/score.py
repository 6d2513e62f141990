#!/usr/bin/python3
"""score.py OUTDIR PREFIX... : counts per case from out/<rec>.truth.json and out/<rec>.{long,short}.json"""
import json, sys, os, glob
import numpy as np

EQUIV = {  # acceptable names for out-of-catalogue effects (docs: README 'out of catalogue as its equivalent or unexplained')
    'telegraph': {'gauss_markov', 'bias_jumps', 'random_walk'},
    'noise_burst': {'noise_level_change'},
}
CUT = 900.0


def present_in_cut(e):
    k = e['effect']
    if k == 'bias_jumps':
        return e['t_step_s'] < CUT
    if k == 'noise_burst':
        return e['window_s'][0] < CUT
    if k == 'outliers':
        return sum(1 for t in e['t_s'] if t < CUT) > 0
    if k == 'telegraph':
        return sum(1 for t in e['switch_t_s'] if t < CUT) > 0
    return True


def matches(effect, names):
    acc = EQUIV.get(effect, {effect})
    return [n for n in names if n in acc]


def score(outdir, prefixes, length):
    rows = {'clean': [0, 0, 0], 'one': [0, 0, 0], 'two': [0, 0, 0, 0], 'ooc': [0, 0]}
    fa_list = []
    mis = {'one': [], 'two': []}
    per_eff = {}
    times = []
    for p in prefixes:
        for tf in sorted(glob.glob(os.path.join(outdir, p + '*.truth.json'))):
            r = os.path.basename(tf)[:-len('.truth.json')]
            jf = os.path.join(outdir, f'{r}.{length}.json')
            if not os.path.exists(jf):
                continue
            truth = json.load(open(tf))
            d = json.load(open(jf))
            tt = open(os.path.join(outdir, f'{r}.{length}.time')).read().split()
            times.append((r, float(tt[0]), int(tt[1]) // 1024, tt[2], truth['n'] if length == 'long' else int(truth['fs'] * CUT)))
            for ax in d['axes']:
                c = ax['channel']
                effs = truth['channels'][c]
                if length == 'short':
                    effs = [e for e in effs if present_in_cut(e)]
                names = [f['effect'] for f in ax['findings'] if f.get('reported')]
                names_x = names + (['noise_level_change'] if ax.get('noise_level_change') else [])
                unexpl = bool(ax.get('unexplained') or ax.get('unexplained_steps'))
                if not effs:
                    rows['clean'][0] += 1
                    if names:
                        rows['clean'][1] += 1
                        fa_list.append((r, c, names))
                    if unexpl:
                        rows['clean'][2] += 1
                    continue
                key = 'one' if len(effs) == 1 else 'two'
                R = rows[key]
                R[0] += 1
                truths = [e['effect'] for e in effs]
                if names and any(matches(t, names[:1]) for t in truths):
                    R[1] += 1
                if any(matches(t, names_x) for t in truths):
                    R[2] += 1
                if key == 'two' and all(matches(t, names_x) for t in truths):
                    R[3] += 1
                for e in effs:
                    k = e['effect']
                    pe = per_eff.setdefault(k, [0, 0, 0])
                    pe[0] += 1
                    if matches(k, names_x):
                        pe[1] += 1
                    if names and matches(k, names[:1]):
                        pe[2] += 1
                    if k in EQUIV:
                        rows['ooc'][0] += 1
                        if matches(k, names_x) or unexpl:
                            rows['ooc'][1] += 1
                acc = set().union(*[EQUIV.get(t, {t}) for t in truths])
                extra = [n for n in names if n not in acc]
                if extra:
                    rows.setdefault('extra', []).append((r, c, truths, names))
                mb, ma = ax.get('misfit_before'), ax.get('misfit_after')
                if mb is not None and ma is not None:
                    mis[key].append((mb, ma))
    return rows, fa_list, mis, per_eff, times


def fmt(rows, mis):
    out = []
    c = rows['clean']
    out.append(f"clean channels: false alarm (reported finding) {c[1]}/{c[0]}; 'unexplained' only {c[2]}/{c[0]}")
    for k in ('one', 'two'):
        R = rows[k]
        s = f"{k}-effect channels: top-1 right {R[1]}/{R[0]}; any truth among reported {R[2]}/{R[0]}"
        if k == 'two':
            s += f"; both found {R[3]}/{R[0]}"
        m = mis[k]
        if m:
            b = np.array([x[0] for x in m]); a = np.array([x[1] for x in m])
            s += (f"; misfit median {np.median(b):.3f} -> {np.median(a):.3f}, lowered {int((a < b - 1e-9).sum())}/{len(m)},"
                  f" halved {int(((a <= b / 2) & (b > 0)).sum())}/{len(m)}, raised {int((a > b + 1e-9).sum())}/{len(m)}")
        out.append(s)
    o = rows['ooc']
    ex = rows.get('extra', [])
    out.append(f"effect channels with a reported finding matching no hidden effect: {len(ex)}/{rows['one'][0] + rows['two'][0]} {ex}")
    out.append(f"out-of-catalogue effects as equivalent or unexplained: {o[1]}/{o[0]}")
    return '\n'.join(out)


if __name__ == '__main__':
    outdir = sys.argv[1]
    prefixes = sys.argv[2:]
    for length in ('long', 'short'):
        rows, fa, mis, pe, times = score(outdir, prefixes, length)
        print(f'== {length} ({" ".join(prefixes)})')
        print(fmt(rows, mis))
        print('false alarms:', fa)
        print('per effect [n, found anywhere, first]:', pe)
        print('times (rec, wall s, peak MB, rc, samples/channel):', times)
