from eff import *
a=run('st_a','gyro:\n  all:\n    - {type: white, density: 0.2 deg/sqrt(h)}\naccel: {}\n',scen=STAT,dur=5)
b=run('st_b','gyro:\n  all:\n    - {type: white, density: 0.2 deg/sqrt(h)}\naccel:\n  all:\n    - {type: white, density: 0.05 m/s/sqrt(h)}\n    - {type: bias, sigma: 1 mg}\n',scen=STAT,dur=5)
c=run('st_c','gyro:\n  all:\n    - {type: white, density: 0.2 deg/sqrt(h)}\n  z:\n    - {type: white, density: 0.2 deg/sqrt(h)}\naccel: {}\n',scen=STAT,dur=5)
w=lambda d: arr(d,'w')-arr(d,'w','ideal')
print('gyro stream unchanged by adding accel effects:',np.array_equal(w(a),w(b)))
print('gyro x,y unchanged by adding z effect:',np.array_equal(w(a)[:,:2],w(c)[:,:2]), ' z differs:', not np.array_equal(w(a)[:,2],w(c)[:,2]), ' corr z-extra vs x', np.corrcoef(w(c)[:,2]-w(a)[:,2], w(a)[:,0])[0,1], np.corrcoef(w(c)[:,2]-w(a)[:,2], w(a)[:,2])[0,1])
# gyro x vs accel x independence
print('corr gyro x / accel x noise', np.corrcoef(w(b)[:,0], (arr(b,'f')-arr(b,'f','ideal'))[:,0])[0,1])
