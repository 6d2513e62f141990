from move_check import *
D=np.radians
import subprocess
y="""name: off
start: {latitude: -20 deg, longitude: 30 deg, height: 300 m, speed: 80 m/s, attitude: {roll: 10 deg, pitch: 5 deg, yaw: 200 deg}}
imu_rate: 100 Hz
output_rate: 100 Hz
vertical: held
segments:
  - {type: turn, heading_change: 50 deg, duration: 20 s, bank: auto}
  - {type: climb, height_change: 200 m, duration: 20 s}
"""
open('off.yaml','w').write(y); r=subprocess.run([BIN,'run','off.yaml','-o','o_off','--imu'],capture_output=True,text=True); print(r.stderr)
tr=np.genfromtxt('o_off/truth.csv',delimiter=',',names=True); im=np.genfromtxt('o_off/imu.csv',delimiter=',',names=True)
g0=9.80665
def prof(t):
    if t<=20:
        u=max(t/20,0); pd=D(50)/20*(1-np.cos(2*np.pi*u)); return (80.0,D(200)+D(50)*S(u),0.0,D(10)+np.arctan(80*pd/g0),D(5))
    u=min((t-20)/20,1); hd=200/20*(1-np.cos(2*np.pi*u)); g=np.arcsin(hd/80); return (80.0,D(250),g,D(10),D(5)+g)
ef,ew=check('offsets turn+climb',tr,im,prof)
# truth Euler vs prof
t=tr['t_s']; P=np.array([prof(x) for x in t])
print('roll diff deg',np.abs(tr['roll_deg']-np.degrees(P[:,3])).max(),' pitch diff',np.abs(tr['pitch_deg']-np.degrees(P[:,4])).max(),' yaw diff',np.abs(((tr['yaw_deg']-np.degrees(P[:,1]))+180)%360-180).max())
idx=np.linspace(1,len(im)-1,25).astype(int); print([(round(im['t_s'][k],2),'%.1e'%e) for k,e in zip(idx,ef)])
