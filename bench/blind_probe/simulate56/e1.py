from eff import *
D=np.pi/180
d=run('sf','gyro:\n  triad:\n    - {type: scale_factor, diagonal: [300 ppm, -200 ppm, 150 ppm]}\naccel:\n  triad:\n    - {type: scale_factor, value: 1 %}\n')
wi,wm=arr(d,'w','ideal'),arr(d,'w'); fi,fm=arr(d,'f','ideal'),arr(d,'f')
S=np.diag([300e-6,-200e-6,150e-6]); print('gyro SF max resid',np.abs(wm-wi@(np.eye(3)+S).T).max(), 'signal max',np.abs(wi).max())
print('accel SF 1% resid',np.abs(fm-1.01*fi).max())
M=np.array([[0,0.1*D,0],[-0.05*D,0,0.2e-3],[0,0,0]])
d=run('mis','gyro:\n  triad:\n    - {type: misalignment, matrix: [[0, 0.1 deg, 0], [-0.05 deg, 0, 0.2 mrad], [0, 0, 0]]}\naccel: {}\n')
wi,wm=arr(d,'w','ideal'),arr(d,'w'); print('gyro mis resid',np.abs(wm-wi@(np.eye(3)+M).T).max(),' transposed-M resid',np.abs(wm-wi@(np.eye(3)+M)).max())
d=run('sfmis','gyro:\n  triad:\n    - {type: scale_factor, diagonal: [300 ppm, -200 ppm, 150 ppm]}\n    - {type: misalignment, matrix: [[0, 0.1 deg, 0], [-0.05 deg, 0, 0.2 mrad], [0, 0, 0]]}\naccel: {}\n')
wi,wm=arr(d,'w','ideal'),arr(d,'w')
A=(np.eye(3)+M)@(np.eye(3)+S); B=(np.eye(3)+S)@(np.eye(3)+M)
print('order (I+M)(I+S) resid',np.abs(wm-wi@A.T).max(),' (I+S)(I+M) resid',np.abs(wm-wi@B.T).max(), ' diff between orders', np.abs(wi@A.T-wi@B.T).max())
# increments consistent
print('increment/dt vs rate', np.abs(arr(d,'th')/0.01-wm).max())
G=0.01*D/9.80665
d=run('gs','gyro:\n  triad:\n    - {type: g_sensitivity, value: 0.01 deg/s/g}\naccel: {}\n')
wi,wm=arr(d,'w','ideal'),arr(d,'w'); fi=arr(d,'f','ideal')
print('gsens resid',np.abs(wm-wi-G*fi).max(),' size',np.abs(G*fi).max())
d=run('gsm','gyro:\n  triad:\n    - {type: g_sensitivity, matrix: [[0.01 deg/s/g, 0.02 deg/s/g, 0], [0,0,0], [0, 0, 0.03 deg/s/g]]}\naccel:\n  triad:\n    - {type: scale_factor, value: 10 %}\n')
wi,wm=arr(d,'w','ideal'),arr(d,'w'); fi=arr(d,'f','ideal'); fmeas=arr(d,'f')
Gm=np.array([[0.01,0.02,0],[0,0,0],[0,0,0.03]])*D/9.80665
print('gsens matrix (ideal f) resid',np.abs(wm-wi-fi@Gm.T).max(),' (meas f) resid',np.abs(wm-wi-fmeas@Gm.T).max())
