from move_check import *
D=np.radians
s=100.; T=20.; dpsi=D(60)
tr,im=mk('ta',45,1000,s,0,'{type: turn, heading_change: 60 deg, duration: 20 s, bank: auto}')
t=tr['t_s']; u=np.clip(t/T,0,1); psid=dpsi/T*(1-np.cos(2*np.pi*u))
for name,g0 in [('g(lat,h)',wgs.somigliana(45,1000)),('g(lat,0)',wgs.somigliana(45,0)),('9.80665',9.80665)]:
    r=np.arctan(s*psid/g0); print(name,'max roll diff deg',np.max(abs(np.degrees(r)-tr['roll_deg'])))
# with the sinsim roll, check centripetal/specific force: lateral f_y should be ~0 (coordinated)
fy=im['ideal_fy_mps2']; print('max |f_y| coordinated',np.max(abs(fy)))
g0=9.80665
def prof(tt):
    uu=min(max(tt/T,0),1); pd=dpsi/T*(1-np.cos(2*np.pi*uu)); return (s,dpsi*S(uu),0.0,np.arctan(s*pd/g0),0.0)
check('auto turn',tr,im,prof)
# bank angle sets duration
tr,im=mk('tb',45,1000,s,0,'{type: turn, heading_change: 90 deg, bank: 30 deg}')
Texp=2*s*D(90)/(g0*np.tan(D(30)))
print('bank 30 turn duration got',tr['t_s'][-1],'exp (g0=9.80665)',Texp, 'exp g(45,1000)',2*s*D(90)/(wgs.somigliana(45,1000)*np.tan(D(30))), 'max roll',tr['roll_deg'].max(), 'end hdg', tr['yaw_deg'][-1])
