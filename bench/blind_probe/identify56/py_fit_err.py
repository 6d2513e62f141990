import warnings,sinsim,numpy as np,json
warnings.simplefilter('ignore')
rng=np.random.default_rng(0); x=rng.standard_normal(20000)*0.01
rec={'gx':x,'rate':100}
def t(name,f):
    try: r=f(); print(f'{name}: OK', (r.yaml()[-160:].replace('\n',' | ') if hasattr(r,'yaml') else ''))
    except BaseException as e: print(f'{name}: {type(e).__name__}: {str(e)[:200]}')
F=sinsim.fit
t('order 0',lambda:F(rec,kind='ar',order=0))
t('order -1',lambda:F(rec,kind='ar',order=-1))
t('order 65',lambda:F(rec,kind='ar',order=65))
t('max_order -1',lambda:F(rec,kind='ar',max_order=-1))
t('max_order 65',lambda:F(rec,kind='ar',max_order=65))
t('kind xyz',lambda:F(rec,kind='xyz'))
t('criterion xyz',lambda:F(rec,kind='ar',criterion='xyz'))
t('axes gq',lambda:F(rec,kind='ar',axes=['gq']))
t('axes gy absent',lambda:F(rec,kind='ar',axes=['gy']))
t('skip beyond',lambda:F(rec,kind='ar',skip=1000.0))
t('skip neg',lambda:F(rec,kind='ar',skip=-5.0))
t('skip nan',lambda:F(rec,kind='ar',skip=float('nan')))
t('skip str',lambda:F(rec,kind='ar',skip='1 min'))
t('skip bad unit',lambda:F(rec,kind='ar',skip='1 m'))
t('lines xyz',lambda:F(rec,kind='ar',lines='xyz'))
t('gyro_unit blah (dict)',lambda:F(rec,kind='ar',gyro_unit='blah'))
a=sinsim.analyze('/tmp/probe_A/syn.csv',rate=100,denoise=True)
b=json.load(open('/tmp/probe_A/a_dn.json'))['channels']['gx']
print('py denoise acf r0',a['gx']['acf']['r'][0],'cli',b['acf']['r'][0])
