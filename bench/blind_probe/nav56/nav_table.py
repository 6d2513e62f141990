import json,glob,sys
for f in sorted(glob.glob(sys.argv[1] if len(sys.argv)>1 else 'dn_*.json')):
    n=json.load(open(f))['navigation']
    for m in [n['model']]+([n['improved']] if 'improved' in n else []):
        b=m['bands_at_rest']
        terms=", ".join(f"{t['sensor']} {t['effect']} {t['share']*100:.0f}%" for t in m['terms'])
        print(f"{f:28s} {m['model'][:10]:10s} end pct {m['record_percentile']:5.1f} ({m['direction']:14s}) med-over-t {m['record_median_percentile_over_time']:5.1f} | band {b['driving_tau_from_s']:.0f}-{b['driving_tau_to_s']:.0f}s share {b['driving_share']:.2f} pct {b['driving_record_percentile']:5.1f} {b['driving_direction']:14s} | {terms} | ratio {m.get('drift_ratio','')} warn {str(m.get('warning',''))[:80]}")
