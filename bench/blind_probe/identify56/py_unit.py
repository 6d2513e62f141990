import sinsim,numpy as np,warnings
rng=np.random.default_rng(0); x=rng.standard_normal(10000)*0.01
a0=sinsim.analyze({'gx':x,'rate':100})
for u in [None,'deg/s','m/s','blah','rad/s']:
    a=sinsim.analyze({'gx':np.degrees(x),'rate':100},gyro_unit=u)
    print(u,'sd',a['gx']['sd'],'unit',a['gx']['unit'])
a=sinsim.analyze({'ax':x,'rate':100},accel_unit='g'); print('accel g sd',a['ax']['sd'])
r=sinsim.load_record('/tmp/probe_A/syn.csv',rate=100); print({k:(getattr(v,'shape',v)) for k,v in r.items()})
try: r=sinsim.load_record('/tmp/probe_A/syn.csv',rate=100,gyro_unit='blah')
except Exception as e: print('load_record bad unit:',type(e).__name__,e)
try: r=sinsim.analyze('/tmp/probe_A/syn.csv',rate=100,gyro_unit='blah')
except Exception as e: print('analyze path bad unit:',type(e).__name__,e)
# round trip: load_record dict into analyze
r=sinsim.load_record('/tmp/probe_A/syn_deg.csv',gyro_unit='deg/s')
print('syn_deg keys',list(r.keys()), r['rate'])
try:
    a=sinsim.analyze(r); print('analyze(load_record) ok sd gx',a['gx']['sd'])
except Exception as e: print('analyze(load_record):',type(e).__name__,e)
