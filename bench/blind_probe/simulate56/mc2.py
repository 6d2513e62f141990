from move_check import *
import move_check
T=30.;dh=300.;s=100.
def climb(t):
    u=min(max(t/T,0),1); hd=dh/T*(1-np.cos(2*np.pi*u)); g=np.arcsin(hd/s); return (s,0.0,g,0.0,g)
tr,im=mk('cl',45,0,100,0,'{type: climb, height_change: 300 m, duration: 30 s}')
# check h vs analytic
t=tr['t_s']; hexp=dh*S(np.clip(t/T,0,1))
print('max |h-hexp|',np.max(abs(tr['h_m']-hexp)), 'end h', tr['h_m'][-1])
k=np.argmax(abs(tr['h_m']-hexp)); print('at t',t[k])
# horizontal distance: north distance integral of s cos gamma
from scipy.integrate import quad
dist=quad(lambda tt: s*np.cos(climb(tt)[2]),0,T,epsabs=1e-12,limit=200)[0]
M,N=wgs.radii(np.radians(45))
print('north dist exp',dist)
