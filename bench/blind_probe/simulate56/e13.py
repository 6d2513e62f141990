from eff import *
D=np.pi/180
d=run('ord','gyro:\n  all:\n    - {type: bias, value: 1 deg/s}\n  triad:\n    - {type: scale_factor, matrix: [[10 %, 1 %, 0], [0, 0, 2 %], [0, 0, 0]]}\naccel: {}\n')
wi,wm=arr(d,'w','ideal'),arr(d,'w'); S=np.array([[0.1,0.01,0],[0,0,0.02],[0,0,0]])
b=np.ones(3)*D
print('(I+S)u + b resid',np.abs(wm-(wi@(np.eye(3)+S).T+b)).max(),'  (I+S)(u+b) resid',np.abs(wm-((wi+b)@(np.eye(3)+S).T)).max(), ' S^T resid',np.abs(wm-(wi@(np.eye(3)+S)+b)).max())
d=run('rwr','gyro:\n  all:\n    - {type: random_walk, K: 100 deg/h/sqrt(h), rate: 200 Hz}\n    - {type: bias, value: 1 deg/h, sigma: 0 deg/h}\naccel:\n  all:\n    - {type: quantization, lsb: 100 deg/h}\n',scen=STAT,dur=500,rate=100)
