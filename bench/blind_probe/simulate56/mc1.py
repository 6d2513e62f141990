from move_check import *
D=np.radians
# A cruise north 30 m/s
tr,im=mk('cn',45,100,30,0,'{type: cruise, duration: 30 s}')
check('cruise N 30m/s lat45',tr,im,lambda t:(30.0,0.0,0.0,0.0,0.0))
tr,im=mk('ce',60,10000,250,90,'{type: cruise, duration: 30 s}')
check('cruise E 250m/s lat60 h10k',tr,im,lambda t:(250.0,D(90),0.0,0.0,0.0))
T=30.;dpsi=D(90)
tr,im=mk('tn',45,0,20,0,'{type: turn, heading_change: 90 deg, duration: 30 s}')
check('car turn 90 in 30s at 20',tr,im,lambda t:(20.0,dpsi*S(min(max(t/T,0),1)),0.0,0.0,0.0))
T=30.;dh=300.;s=100.
def climb(t):
    u=min(max(t/T,0),1); hd=dh/T*(1-np.cos(2*np.pi*u)); g=np.arcsin(hd/s); return (s,0.0,g,0.0,g)
tr,im=mk('cl',45,0,100,0,'{type: climb, height_change: 300 m, duration: 30 s}')
check('climb 300m/30s at 100',tr,im,climb)
def acc(t):
    u=min(max(t/10,0),1); return (20*S(u),D(30),0.0,0.0,0.0)
tr,im=mk('ac',45,0,0,30,'{type: accelerate, speed: 20 m/s, duration: 10 s}')
check('accel 0-20 in 10s hdg 30',tr,im,acc)
