import json, sys, collections
R=[json.loads(l) for l in open(sys.argv[1]+'/results.jsonl')]
t=collections.defaultdict(collections.Counter); rose=[]
for r in R:
    if r['name']=='null': continue
    for c,spec in (('gx',r['fx']),('gz',r['fz'])):
        if not spec: continue
        a=r['diag']['axes'][c]
        if not a['found'] or a['misfit_before'] is None or a['misfit_before']<0.05: continue
        k='+'.join(e for e,_ in spec); x=t[k]; x['n']+=1
        x['halved']+=a['misfit_after']<=0.5*a['misfit_before']; x['rose']+=a['misfit_after']>a['misfit_before']+1e-9
        if a['misfit_after']>a['misfit_before']+1e-9: rose.append((r['key'],c,k,[f[0] for f in a['found']],round(a['misfit_before'],3),round(a['misfit_after'],3)))
        if 'hold_imp' in r:
            ho,hi=r['hold_orig']['axes'][c],r['hold_imp']['axes'][c]; x['hn']+=1; x['hlow']+=hi['misfit']<ho['misfit']; x['hhalf']+=hi['misfit']<=0.5*ho['misfit']; x['hworse']+=hi['misfit']>ho['misfit']+1e-9
print('| truth on channel | n (found, misfit before >= 0.05) | after <= half before | after > before | held-out n | held-out: improved lower | halved | worse |')
print('|---|---|---|---|---|---|---|---|')
for k,x in sorted(t.items()): print(f"| {k} | {x['n']} | {x['halved']}/{x['n']} | {x['rose']}/{x['n']} | {x['hn']} | {x['hlow']}/{x['hn']} | {x['hhalf']}/{x['hn']} | {x['hworse']}/{x['hn']} |")
print('misfit rose:'); [print('  ',z) for z in rose]
