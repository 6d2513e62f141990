import numpy as np, wgs, subprocess
from scipy.integrate import quad
S=lambda u: u-np.sin(2*np.pi*u)/(2*np.pi)
D=np.radians
T=1.005; A=D(30); s=20.0
def roll(t):
    if t<=0: return 0.0
    if t>=T: return 0.0
    if t<=T/2: return A*S(t/(T/2))
    return A*(1-S((t-T/2)/(T/2)))
def rolld(t):
    if t<=0 or t>=T: return 0.0
    if t<=T/2: return A/(T/2)*(1-np.cos(2*np.pi*t/(T/2)))
    return -A/(T/2)*(1-np.cos(2*np.pi*(t-T/2)/(T/2)))
open('kn.yaml','w').write(f"""start: {{latitude: 45 deg, longitude: 7 deg, speed: 20 m/s, heading: 0 deg}}
imu_rate: 100 Hz
output_rate: 100 Hz
vertical: held
segments:
  - {{type: roll, angle: 30 deg, duration: {T} s}}
  - {{type: cruise, duration: 0.995 s}}
""")
subprocess.run(['/tmp/probe_bin3/sinsim','run','kn.yaml','-o','o_kn','--imu'],check=True,capture_output=True)
im=np.genfromtxt('o_kn/imu.csv',delimiter=',',names=True); tr=np.genfromtxt('o_kn/truth.csv',delimiter=',',names=True)
lat0=D(45); M,N=wgs.radii(lat0); gn=wgs.gravity_ned(45,0)
def inst(t):
    lat=lat0+s*t/M
    wie=wgs.WE*np.array([np.cos(lat),0,-np.sin(lat)]); v=np.array([s,0,0]); wen=np.array([0,-s/M,0])
    g=gn  # tiny lat change ignored
    C=wgs.Cnb(roll(t),0,0)
    f=C.T@(np.cross(2*wie+wen,v)-g)
    w=np.array([rolld(t),0,0])+C.T@(wie+wen)
    return np.r_[f,w]
maxe=[]
for k in range(len(im)):
    t=im['t_s'][k]; a=t-0.01
    pts=[x for x in [T/2,T] if a<x<t]
    edges=[a]+pts+[t]
    m=np.zeros(6)
    for i in range(6):
        m[i]=sum(quad(lambda x: inst(x)[i],edges[j],edges[j+1],epsabs=1e-15,epsrel=1e-13)[0] for j in range(len(edges)-1))/0.01
    got=np.r_[im['ideal_fx_mps2'][k],im['ideal_fy_mps2'][k],im['ideal_fz_mps2'][k],im['ideal_wx_radps'][k],im['ideal_wy_radps'][k],im['ideal_wz_radps'][k]]
    maxe.append(np.abs(got-m))
maxe=np.array(maxe); t=im['t_s']
i=np.argmax(maxe[:,:3].max(1)); j=np.argmax(maxe[:,3:].max(1))
print('max |df|',maxe[:,:3].max(),'at',t[i],' max |dw|',maxe[:,3:].max(),'at',t[j])
for tt in [0.5,0.51,1.0,1.01]:
    k=np.argmin(abs(t-tt)); print(tt, maxe[k])
