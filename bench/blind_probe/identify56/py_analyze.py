import sys,json,warnings,numpy as np
sys.path.insert(0,'/tmp/probe_A'); from util import *
import sinsim
warnings.simplefilter('always')
with warnings.catch_warnings(record=True) as wl:
    a=sinsim.analyze('/tmp/probe_A/syn.csv',rate=100)
print('warnings:',[str(w.message)[:100] for w in wl])
print('keys',list(a.keys()))
c=a['gx'] if 'gx' in a else a[list(a.keys())[0]]
print({k:(type(v).__name__, getattr(v,'shape',None) if not isinstance(v,dict) else {kk:getattr(vv,'shape',vv) for kk,vv in v.items()}) for k,v in c.items()})
d=json.load(open('/tmp/probe_A/a_full.json'))
s=np.load('/tmp/probe_A/syn.npz')
for ch,key in zip(['gx','gy','gz','ax','ay','az'],['w','ar2','ar5','gm','rw','acc']):
    c=a[ch]; j=d['channels'][ch]; x=s[key]
    print(ch,'unit',c['unit'],'mean',c['mean']-j['mean'],'sd',c['sd'],j['std'],'const',c['constant'])
    print('  allan tau eq',np.array_equal(c['allan']['tau'],j['allan']['tau_s']),'adev eq',np.max(np.abs(c['allan']['adev']/np.array(j['allan']['adev'])-1)), 'lo/hi',np.max(np.abs(c['allan']['lo']/np.array(j['allan']['lo'])-1)),np.max(np.abs(c['allan']['hi']/np.array(j['allan']['hi'])-1)))
    print('  psd len',len(c['psd']['f']),len(j['psd']['f_hz']),'maxrel',np.max(np.abs(c['psd']['psd']/np.array(j['psd']['psd'])-1)) if len(c['psd']['f'])==len(j['psd']['f_hz']) else 'n/a')
    print('  acf len',len(c['acf']['lag']),len(j['acf']['lag_s']), 'maxabs', np.max(np.abs(c['acf']['r']-np.array(j['acf']['r']))) if len(c['acf']['lag'])==len(j['acf']['lag_s']) else 'n/a', 'r0',c['acf']['r'][0], j['acf']['r'][0])
