import numpy as np,csv,sys
d=sys.argv[1]; sig=float(sys.argv[2])
lat=np.radians(45); ge=9.7803253359*(1+0.00193185265241*np.sin(lat)**2)/np.sqrt(1-0.00669437999013*np.sin(lat)**2)-3.086e-6*250
a=6378137.0; e2=0.00669437999013; RN=a*(1-e2)/(1-e2*np.sin(lat)**2)**1.5; RE=a/np.sqrt(1-e2*np.sin(lat)**2)
rows=list(csv.DictReader(open(f"{d}/per_run.csv")))
def ci(xs,p,z=2.576):
    n=len(xs); m=n*p; h=z*np.sqrt(n*p*(1-p)); return xs[max(0,int(m-h)-1)], xs[min(n-1,int(m+h))]
for t in sorted(set(float(r['t [s]']) for r in rows)):
    x=np.array([float(r['horizontal [m]']) for r in rows if float(r['t [s]'])==t])
    ws=np.sqrt(ge/np.sqrt(RN*RE)); s=sig*(1-np.cos(ws*t))/ws**2
    xs=np.sort(x); lo,hi=ci(xs,0.5); lo95,hi95=ci(xs,0.95)
    u=np.sort(1-np.exp(-(xs/s)**2/2)); n=len(u); D=max(np.max(np.arange(1,n+1)/n-u),np.max(u-np.arange(n)/n))
    print(f"t={t}: CEP {np.median(x):.1f} [99% {lo:.1f},{hi:.1f}] vs Rayleigh {1.17741*s:.1f};  R95 {np.percentile(x,95):.1f} [{lo95:.1f},{hi95:.1f}] vs {2.44775*s:.1f}; KS D={D:.3f} (1% crit {1.63/np.sqrt(n):.3f})")
