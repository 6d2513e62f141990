import sinsim,numpy as np,warnings
x=np.random.default_rng(0).standard_normal(10000)*0.01
# 1) unit options silently ignored for dict records (even invalid ones)
for u in [None,'deg/s','blah']:
    print('gyro_unit',u,'-> sd',sinsim.analyze({'gx':np.degrees(x),'rate':100},gyro_unit=u)['gx']['sd'])
# 2) dict rate given as a unit string -> RuntimeError, not InputError
try: sinsim.analyze({'gx':x,'rate':'100 Hz'})
except Exception as e: print(type(e).__mro__[:3], e)
# 3) analyze raises no Python warnings where the CLI warns (ms time stamps, constant channel, units)
with warnings.catch_warnings(record=True) as wl:
    warnings.simplefilter('always')
    a=sinsim.analyze('/tmp/probe_A/bad/tms.csv'); b=sinsim.analyze('/tmp/probe_A/bad/const.csv')
print('python warnings from analyze(tms.csv)+analyze(const.csv):',len(wl))
