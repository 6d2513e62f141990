import warnings,sinsim
warnings.simplefilter('always')
for fn,kw in [('analyze',{}),('fit',{'kind':'ar','axes':['gy']}),('load_record',{})]:
    with warnings.catch_warnings(record=True) as wl:
        warnings.simplefilter('always')
        r=getattr(sinsim,fn)('/tmp/probe_A/syn.csv',rate=100,**kw)
    print(fn,len(wl),[str(w.message)[:90] for w in wl])
# const channel
with warnings.catch_warnings(record=True) as wl:
    warnings.simplefilter('always')
    r=sinsim.analyze('/tmp/probe_A/bad/const.csv')
print('const analyze',len(wl),[str(w.message)[:90] for w in wl], r['gx']['constant'], r['gx']['sd'])
with warnings.catch_warnings(record=True) as wl:
    warnings.simplefilter('always')
    r=sinsim.analyze('/tmp/probe_A/bad/tms.csv')
print('tms analyze',len(wl),[str(w.message)[:90] for w in wl])
