from move_check import *
D=np.radians; s=100.; T=20.; dpsi=D(60); g0=9.80665
tr=np.genfromtxt('o_ta/truth.csv',delimiter=',',names=True); im=np.genfromtxt('o_ta/imu.csv',delimiter=',',names=True)
def prof(tt):
    uu=min(max(tt/T,0),1); pd=dpsi/T*(1-np.cos(2*np.pi*uu)); return (s,dpsi*S(uu),0.0,np.arctan(s*pd/g0),0.0)
ef,ew=check('auto turn',tr,im,prof); print(np.array(ew))
