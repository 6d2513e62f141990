import numpy as np, csv, json, sys
d=sys.argv[1]
rows=list(csv.DictReader(open(f"{d}/per_run.csv")))
S=list(csv.DictReader(open(f"{d}/stats.csv")))
J=json.load(open(f"{d}/summary.json"))
from collections import defaultdict
grp=defaultdict(list)
for r in rows: grp[(r['model'],float(r['t [s]']))].append(r)
maxrel=0; n=0
cols={'horizontal_m':lambda r: float(r['horizontal [m]']),'vertical_m':lambda r: abs(float(r['vertical [m]'])),
 'velocity_mps':lambda r: np.sqrt(sum(float(r[k])**2 for k in ['vn [m/s]','ve [m/s]','vd [m/s]'])),
 'roll_abs_rad':lambda r: abs(float(r['roll [rad]'])),'pitch_abs_rad':lambda r: abs(float(r['pitch [rad]'])),'yaw_abs_rad':lambda r: abs(float(r['yaw [rad]']))}
for s in S:
    key=(s['model'],float(s['t_s']))
    if key not in grp: continue
    rs=grp[key]
    for c,f in cols.items():
        x=np.array([f(r) for r in rs])
        ref={'mean':x.mean(),'sd':x.std(ddof=1),'rms':np.sqrt((x**2).mean()),'p50':np.percentile(x,50),'p68':np.percentile(x,68),'p95':np.percentile(x,95),'p99':np.percentile(x,99)}
        for k,v in ref.items():
            got=float(s[f"{c}_{k}"]); rel=abs(got-v)/max(abs(v),1e-12)
            n+=1
            if rel>1e-5 and abs(got-v)>1e-9: print("MISMATCH",key,c,k,"got",got,"ref",v,"rel",rel)
            maxrel=max(maxrel,rel if abs(got-v)>1e-9 else 0)
    # signed
    for c,k in [('north_m','north [m]'),('east_m','east [m]'),('down_m','down [m]'),('yaw_rad','yaw [rad]'),('roll_rad','roll [rad]')]:
        x=np.array([float(r[k]) for r in rs])
        for kk,v in [('mean',x.mean()),('sd',x.std(ddof=1))]:
            nm=f"{c}_{kk}"
            if nm in s:
                got=float(s[nm]); n+=1
                if abs(got-v)>1e-5*max(abs(v),1) : print("MISMATCH signed",key,nm,got,v)
print("checked",n,"values over",len(S),"stats rows (present in per_run:",sum(1 for s in S if (s['model'],float(s['t_s'])) in grp),") maxrel",maxrel)
for m in J['models']:
    for a in m['at']:
        x=np.array([float(r['horizontal [m]']) for r in grp[(m['label'],a['t_s'])]]) if (m['label'],a['t_s']) in grp else None
        if x is None: print("no per_run for",a['t_s'], m.keys()); continue
        print(m['label'],a['t_s'],"CEP",a['cep_m'],np.median(x),"R95",a['r95_m'],np.percentile(x,95))
