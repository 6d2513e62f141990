#!/usr/bin/python3
"""--skip/--duration across formats: same samples?"""
import json, subprocess, sys, hashlib
B = '/tmp/probe_bin58/sinsim'
V = {v['name']: v for v in json.load(open('variants.json'))}
names = ['ref', 't_ms_hdr', 't_us_hdr', 't_ns_hdr', 't_epoch_s6', 't_epoch_s3', 't_epoch_s9', 't_epoch_ms', 't_epoch_ns', 't_offset', 't_negative_start', 'no_time_rate', 'headerless_map', 'gz', 'semicolon', 'vendor_names_map', 't_jitter0.4', 't_jitter1_allow', 't_gap_allow']
cuts = [['--skip', '60', '--duration', '300'], ['--skip', '1 min', '--duration', '10 s'], ['--skip', '0.005'], ['--skip', '0.015', '--duration', '0.995'], ['--duration', '599.99'], ['--duration', '600'], ['--skip', '599.97'], ['--skip', '599.99']]
for c in cuts:
    print('###', ' '.join(c))
    for n in names:
        v = V[n]
        p = subprocess.run([B, 'analyze', v['file'], '--json', 'sd.json'] + v['args'] + c, capture_output=True, text=True)
        if p.returncode == 0:
            d = json.load(open('sd.json'))
            g = d['channels']['gx']
            sig = '%d %.6f mean=%.12e adev0=%.12e' % (d['samples'], d['rate_hz'], g['mean'], g['allan']['adev'][0] if g['allan']['adev'] else float('nan'))
        else:
            sig = 'rc=%d %s' % (p.returncode, p.stderr.strip().splitlines()[-1][:200])
        print('  %-20s %s' % (n, sig), flush=True)
