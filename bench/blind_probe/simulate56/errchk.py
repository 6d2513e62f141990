import numpy as np, json, wgs, sys
o=sys.argv[1]
T=np.genfromtxt(o+'/truth.csv',delimiter=',',names=True); N=np.genfromtxt(o+'/nav.csv',delimiter=',',names=True); E=np.genfromtxt(o+'/errors.csv',delimiter=',',names=True)
lat=np.radians(T['lat_deg']); M,Nr=wgs.radii(lat); h=T['h_m']
dlon=(N['lon_deg']-T['lon_deg']+180)%360-180
n=np.radians(N['lat_deg']-T['lat_deg'])*(M+h); e=np.radians(dlon)*(Nr+h)*np.cos(lat); d=-(N['h_m']-h)
print('lon range truth',T['lon_deg'].min(),T['lon_deg'].max())
print('north resid',np.abs(n-E['north_m']).max(),' east',np.abs(e-E['east_m']).max(),' down',np.abs(d-E['down_m']).max(), ' rel east', np.abs(e-E['east_m']).max()/np.abs(e).max())
for k in ['vn_mps','ve_mps','vd_mps']: print(k,np.abs(N[k]-T[k]-E[k]).max())
wrap=lambda x:(x+180)%360-180
for a,b in [('roll_deg','roll_rad'),('pitch_deg','pitch_rad'),('yaw_deg','yaw_rad')]: print(b,np.abs(np.radians(wrap(N[a]-T[a]))-E[b]).max(), 'max',np.abs(E[b]).max())
S=json.load(open(o+'/summary.json'))
hz=np.hypot(E['north_m'],E['east_m']); print('final horiz csv',hz[-1],'json',S['final_error']['horizontal_m'],' rms csv',np.sqrt(np.mean(hz**2)),'json',S['rms_error']['horizontal_m'], ' max csv',hz.max(),'json(all epochs)',S['max_error']['horizontal_m'])
print('vert final', abs(E['down_m'][-1]), S['final_error']['vertical_m'], 'rms', np.sqrt(np.mean(E['down_m']**2)), S['rms_error']['vertical_m'])
dist=np.sum(np.hypot(np.diff(np.radians(T['lat_deg']))*(M[1:]+h[1:]), np.radians((np.diff(T['lon_deg'])+180)%360-180)*(Nr[1:]+h[1:])*np.cos(lat[1:]))); print('distance approx',dist,'json',S['distance_m'])
