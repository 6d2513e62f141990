import json,glob,csv,numpy as np,sys
pat=sys.argv[1]
for t in [120,300,600]:
    rec=[];mod=[]
    for d in sorted(glob.glob(pat)):
        J=json.load(open(d+'summary.json'))['measured']['models'][0]
        rec+= [a['measured_horizontal_m'] for a in J['at'] if a['t_s']==t]
        mod+= [float(r['horizontal [m]']) for r in csv.DictReader(open(d+'per_run.csv')) if float(r['t [s]'])==t]
    rec=np.array(rec);mod=np.array(mod)
    allv=np.sort(np.concatenate([rec,mod])); F1=np.searchsorted(np.sort(rec),allv,side='right')/len(rec); F2=np.searchsorted(np.sort(mod),allv,side='right')/len(mod)
    D=np.max(abs(F1-F2)); n,m=len(rec),len(mod); crit=1.63*np.sqrt((n+m)/(n*m))
    print(f"t={t}: records n={n} median {np.median(rec):.1f} rms {np.sqrt(np.mean(rec**2)):.1f} | model runs n={m} median {np.median(mod):.1f} rms {np.sqrt(np.mean(mod**2)):.1f} | KS D={D:.3f} (1% crit {crit:.3f})")
