import numpy as np,csv,sys
d=sys.argv[1]; n=float(sys.argv[2])*np.pi/180/60
lat=np.radians(45); ge=9.7803253359*(1+0.00193185265241*np.sin(lat)**2)/np.sqrt(1-0.00669437999013*np.sin(lat)**2)-3.086e-6*250
a=6378137.0; e2=0.00669437999013; RN=a*(1-e2)/(1-e2*np.sin(lat)**2)**1.5; RE=a/np.sqrt(1-e2*np.sin(lat)**2)
ws=np.sqrt(ge/np.sqrt(RN*RE))
rows=list(csv.DictReader(open(f"{d}/per_run.csv")))
for t in sorted(set(float(r['t [s]']) for r in rows)):
    sel=[r for r in rows if float(r['t [s]'])==t]
    x=np.array([float(r['horizontal [m]']) for r in sel]); N=np.array([float(r['north [m]']) for r in sel]); E=np.array([float(r['east [m]']) for r in sel])
    u=np.linspace(0,t,200001); K=(1-np.cos(ws*u))/ws**2; var=ge**2*n**2*np.trapz(K**2,u); s=np.sqrt(var)
    m=len(x)
    print(f"t={t}: var N/theory {np.mean(N**2)/var:.3f} E {np.mean(E**2)/var:.3f} (99.9% chi2 ~ [{1-3.29*np.sqrt(2/m):.2f},{1+3.29*np.sqrt(2/m):.2f}]); CEP {np.median(x):.0f} vs {1.17741*s:.0f}; R95 {np.percentile(x,95):.0f} vs {2.44775*s:.0f}")
