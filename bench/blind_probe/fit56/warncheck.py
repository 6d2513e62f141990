import glob, re, sys
sys.argv=['x','a','1','auto']
src=open('score.py').read().replace('\nmain()\n','\n')
exec(src)
miss=0; tot=0; extra=0
for f in sorted(glob.glob('*_[0-9]*.*.yaml')):
    if f.startswith('syn') or f.startswith('rep'): continue
    for ch, effs in parse(f).items():
        allc = ' '.join(' '.join(e['c']) for e in effs)
        for e in effs:
            p=e['p']; t=e['type']
            for key, comkey in [('density',None),('sigma','sigma'),('tau','tau'),('K',None),('B',None),('slope',None)]:
                if key not in p: continue
                if t=='gauss_markov' and comkey is None: continue
                try: v=abs(q(p[key])); s=sig_of(e['c'], comkey)
                except Exception: continue
                if s!=s: continue
                if s > v:
                    tot+=1
                    if 'WARNING' not in allc or 'exceeds' not in allc:
                        miss+=1; print('NO WARNING', f, ch, t, key, v, s)
print('params with 1sigma>value:', tot, 'without warning:', miss)
