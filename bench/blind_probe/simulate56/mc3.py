from move_check import *
T=30.;dh=300.;s=100.
def climb(t):
    u=min(max(t/T,0),1); hd=dh/T*(1-np.cos(2*np.pi*u)); g=np.arcsin(hd/s); return (s,0.0,g,0.0,g)
im=np.genfromtxt('o_cl/imu.csv',delimiter=',',names=True); tr=np.genfromtxt('o_cl/truth.csv',delimiter=',',names=True)
import move_check
# replicate check but print per-sample
ef,ew=check('climb',tr,im,climb)
print(np.array(ef))
