import numpy as np, wgs
from scipy.integrate import solve_ivp
D=np.radians
S=lambda u: u-np.sin(2*np.pi*u)/(2*np.pi)
# segments: (T, kind, delta)
segs=[(5,'none',0),(20,'s',50),(40,'psi',D(-120)),(60,'h',500),(100,'none',0),(30,'psi',None),(50,'h',None),(15,'s',-40)]
# resolve targets: heading after first turn 45-120=-75 -> target 170: shortest: 170-(-75)=245 -> -115
segs[5]=(30,'psi',D(-115)); segs[6]=(50,'h',100-550)
def state_at(t):
    s,psi,h,hd=0.0,D(45),50.0,0.0; t0=0
    for T,k,dl in segs:
        if t<=t0+T:
            u=(t-t0)/T
            if k=='s': s=s+dl*S(u)
            if k=='psi': psi=psi+dl*S(u)
            if k=='h': hd=dl/T*(1-np.cos(2*np.pi*u))
            return s,psi,hd
        if k=='s': s+=dl
        if k=='psi': psi+=dl
        t0+=T
    return s,psi,0.0
knots=np.cumsum([0]+[x[0] for x in segs])
y=np.array([D(30),D(100),50.0]); dist=0
for a,b in zip(knots[:-1],knots[1:]):
    def rhs(t,y):
        lat,lon,h,d=y; s,psi,hd=state_at(t)
        g=np.arcsin(hd/s) if s>0 else 0
        M,N=wgs.radii(lat)
        return [s*np.cos(g)*np.cos(psi)/(M+h), s*np.cos(g)*np.sin(psi)/((N+h)*np.cos(lat)), hd, s]
    sol=solve_ivp(rhs,(a,b),list(y)+[dist],rtol=1e-13,atol=1e-14,method='DOP853')
    y=sol.y[:3,-1]; dist=sol.y[3,-1]
print('mine: lat %.12f lon %.12f h %.6f dist %.4f'%(np.degrees(y[0]),np.degrees(y[1]),y[2],dist))
tr=np.genfromtxt('o_traj/truth.csv',delimiter=',',names=True)
M,N=wgs.radii(y[0])
dn=(D(tr['lat_deg'][-1])-y[0])*(M+y[2]); de=(D(tr['lon_deg'][-1])-y[1])*(N+y[2])*np.cos(y[0])
print('diff N %.3e E %.3e h %.3e m; end heading got %s exp %.6f'%(dn,de,tr['h_m'][-1]-y[2],tr['yaw_deg'][-1],np.degrees(D(45-120-115))%360))
