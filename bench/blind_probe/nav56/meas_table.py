import json,glob,csv,numpy as np
P={120:[],300:[],600:[]}; bad=0; med=[]
for d in sorted(glob.glob('/tmp/probe_B/mm_*/')):
    J=json.load(open(d+'summary.json'))['measured']['models'][0]
    med.append(J['median_percentile_over_time'])
    rows=list(csv.DictReader(open(d+'per_run.csv')))
    for a in J['at']:
        x=np.array([float(r['horizontal [m]']) for r in rows if float(r['t [s]'])==a['t_s']])
        m=a['measured_horizontal_m']; mid=100*((x<m).sum()+0.5*(x==m).sum()+0.5)/(len(x)+1)
        mid2=100*((x<m).sum()+0.5*(x==m).sum())/len(x)
        P[int(a['t_s'])].append(a['percentile'])
        if abs(mid-a['percentile'])>1e-6 and abs(mid2-a['percentile'])>1e-6: bad+=1; print("pct mismatch",d,a,mid,mid2)
n=len(med)
for t,p in P.items():
    p=np.array(p); print(f"t={t}: n={len(p)} mean pct {p.mean():.1f} (expect 50 +- {2*28.9/np.sqrt(len(p)):.1f}) tails <=2.5:{(p<=2.5).sum()} >=97.5:{(p>=97.5).sum()} deciles {np.histogram(p,bins=[0,20,40,60,80,100.1])[0]}")
print("median over time:",np.round(np.array(med),1))
