from move_check import *
D=np.radians
tr,im=mk('hl',88.5,5000,250,90,'{type: cruise, duration: 20 s}')
check('cruise E 250 lat 88.5 h5000',tr,im,lambda t:(250.0,D(90),0.0,0.0,0.0))
tr,im=mk('hl2',-88.5,0,250,45,'{type: turn, heading_change: -90 deg, duration: 20 s, bank: auto}')
g0=9.80665
def prof(t):
    u=min(max(t/20,0),1); pd=-D(90)/20*(1-np.cos(2*np.pi*u)); return (250.0,D(45)-D(90)*S(u),0.0,np.arctan(250*pd/g0),0.0)
check('auto turn lat -88.5',tr,im,prof)
