import numpy as np, sys
g=9.80665; 
# local gravity at 45deg, 250m approx
lat=np.radians(45); 
ge=9.7803253359*(1+0.00193185265241*np.sin(lat)**2)/np.sqrt(1-0.00669437999013*np.sin(lat)**2) - 3.086e-6*250
a=6378137.0; e2=0.00669437999013
RN=a*(1-e2)/(1-e2*np.sin(lat)**2)**1.5; RE=a/np.sqrt(1-e2*np.sin(lat)**2)
R=np.sqrt(RN*RE)
for name,kind,val in [("run_abias","a",1e-3*9.80665),("run_gbias","g",np.radians(1)/3600)]:
    d=np.genfromtxt(f"{name}/errors.csv",delimiter=",",names=True)
    t=d['t_s']
    for Rr,lab in [(RN,'RN'),(R,'Rg')]:
        ws=np.sqrt(ge/Rr)
        if kind=="a": cf=val*(1-np.cos(ws*t))/ws**2; obs=d['north_m']
        else: cf=-ge*val*(t-np.sin(ws*t)/ws)/ws**2; obs=d['north_m']
        i=np.argmax(abs(cf))
        print(name,lab,"peak obs %.2f cf %.2f"%(obs[np.argmax(abs(obs))],cf[i]),"max abs diff %.2f m (%.3f%%)"%(np.max(abs(obs-cf)),100*np.max(abs(obs-cf))/np.max(abs(cf))), "east max", np.max(abs(d['east_m'])))
    for tt in [300,600,1200,2700]:
        j=np.searchsorted(t,tt); print("  t",tt,"obs",obs[j],"cf",cf[j])
