#!/usr/bin/python3
"""badgen.py: write bad/odd aided scenarios (variants of city.yaml's gnss/filter keys) into bad/"""
import re
base = open('city.yaml').read()
G = re.search(r'gnss:\n(?:  .*\n)+', base).group(0)
def gnss(rate='1 Hz', ps='[2 m, 2 m, 4 m]', vs='0.1 m/s', la='[1 m, 0.3 m, -1.5 m]', out='[[100 s, 130 s]]', extra=''):
    s = 'gnss:\n'
    if rate is not None: s += f'  rate: {rate}\n'
    if ps is not None: s += f'  position_sigma: {ps}\n'
    if vs is not None: s += f'  velocity_sigma: {vs}\n'
    if la is not None: s += f'  lever_arm: {la}\n'
    if out is not None: s += f'  outages: {out}\n'
    return s + extra
cases = {
 'ovl_outages': gnss(out='[[100 s, 200 s], [150 s, 250 s]]'),
 'dup_outages': gnss(out='[[100 s, 200 s], [100 s, 200 s]]'),
 'unsorted_outages': gnss(out='[[300 s, 330 s], [100 s, 130 s]]'),
 'outage_after_end': gnss(out='[[700 s, 800 s]]'),
 'outage_past_end': gnss(out='[[600 s, 900 s]]'),
 'outage_reversed': gnss(out='[[200 s, 100 s]]'),
 'outage_negative': gnss(out='[[-10 s, 20 s]]'),
 'outage_zero_dur': gnss(out='[{start: 100 s, duration: 0 s}]'),
 'outage_neg_dur': gnss(out='[{start: 100 s, duration: -5 s}]'),
 'outage_nan': gnss(out='[[.nan s, 20 s]]'),
 'outage_whole': gnss(out='[[0 s, 10000 s]]'),
 'outage_scalar': gnss(out='yes'),
 'outage_3elem': gnss(out='[[1 s, 2 s, 3 s]]'),
 'outage_nounit': gnss(out='[[100, 130]]'),
 'rate_200': gnss(rate='200 Hz'),
 'rate_100': gnss(rate='100 Hz'),
 'rate_3': gnss(rate='3 Hz'),
 'rate_7': gnss(rate='7 Hz'),
 'rate_slow': gnss(rate='0.001 Hz'),
 'rate_0': gnss(rate='0 Hz'),
 'rate_neg': gnss(rate='-1 Hz'),
 'rate_nan': gnss(rate='.nan Hz'),
 'rate_inf': gnss(rate='.inf Hz'),
 'rate_huge': gnss(rate='1e9 Hz'),
 'rate_unit': gnss(rate='1 s'),
 'ps_zero': gnss(ps='0 m'),
 'ps_neg': gnss(ps='[-1 m, 1 m, 1 m]'),
 'ps_nan': gnss(ps='[.nan m, 1 m, 1 m]'),
 'ps_huge': gnss(ps='1e11 m'),
 'ps_over': gnss(ps='1e13 m'),
 'ps_tiny': gnss(ps='1e-9 m'),
 'ps_2elem': gnss(ps='[1 m, 1 m]'),
 'vs_zero': gnss(vs='0 m/s'),
 'vs_neg': gnss(vs='-0.1 m/s'),
 'vs_nan': gnss(vs='.nan m/s'),
 'vs_only': gnss(ps=None),
 'no_fix_kind': gnss(ps=None, vs=None),
 'lever_far': gnss(la='[2 km, 0 m, 0 m]'),
 'lever_nan': gnss(la='[.nan m, 0 m, 0 m]'),
 'unknown_key': gnss(extra='  outage: [[1 s, 2 s]]\n'),
}
for k, g in cases.items():
    open(f'bad/{k}.yaml', 'w').write(base.replace(G, g).replace('name: city', f'name: bad_{k}'))
# structural ones
open('bad/no_filter.yaml', 'w').write(re.sub(r'filter: .*\n', '', base))
open('bad/no_gnss.yaml', 'w').write(base.replace(G, ''))
open('bad/filter_missing.yaml', 'w').write(base.replace('filter: {model: tac.yaml}', 'filter: {model: nothere.yaml}'))
open('bad/filter_badmodel.yaml', 'w').write(base.replace('filter: {model: tac.yaml}', 'filter: {model: {gyro: {all: [{type: white, density: -1 deg/sqrt(h)}]}, accel: {}}}'))
open('bad/ie_neg.yaml', 'w').write(base.replace('position: {sigma: 3 m}', 'position: {sigma: -3 m}'))
open('bad/ie_nan.yaml', 'w').write(base.replace('position: {sigma: 3 m}', 'position: {sigma: .nan m}'))
open('bad/ie_huge.yaml', 'w').write(base.replace('position: {sigma: 3 m}', 'position: {sigma: 1e6 m}'))
open('bad/ie_att_huge.yaml', 'w').write(base.replace('attitude: {sigma: [0.3 deg, 0.3 deg, 5 deg]}', 'attitude: {sigma: [0.3 deg, 0.3 deg, 400 deg]}'))
open('bad/align_moving.yaml', 'w').write(base.replace('initial_errors:', 'alignment: {type: coarse, duration: 30 s}\ninitial_errors:'))
open('bad/align_outage.yaml', 'w').write(base.replace('initial_errors:', 'alignment: {type: coarse, duration: 8 s}\ninitial_errors:'))
open('bad/multi.yaml', 'w').write(base.replace(G, gnss(rate='-1 Hz', ps='[-1 m, .nan m, 1 m]', vs='0 m/s', out='[[200 s, 100 s], [700 s, 800 s]]')))
