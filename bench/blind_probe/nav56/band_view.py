import json,sys
for f in sys.argv[1:]:
    b=json.load(open(f))['navigation']['model']['bands_at_rest']
    print(f, "driving", b['driving_tau_from_s'],'-',b['driving_tau_to_s'])
    print("  tau_s   share  model_rms_km record_km  record/model_rms")
    for t,s,m,r in zip(b['tau_s'],b['share'],b['model_rms_m'],b['record_m']):
        if s>0.01 or (m>0 and r/m>2): print("  %7s %5.2f %9.2f %9.2f %6.2f"%(t,s,m/1e3,r/1e3,r/m if m else float('nan')))
