import sinsim,numpy as np,warnings,subprocess,difflib
warnings.simplefilter('always')
for kind in ['ar','gm','auto']:
    with warnings.catch_warnings(record=True) as wl:
        warnings.simplefilter('always')
        m=sinsim.fit('/tmp/probe_A/syn.csv',kind=kind,axes=['gy','gz','ax'],rate=100)
    py=m.yaml()
    subprocess.run(['/tmp/probe_bin1/sinsim','fit','/tmp/probe_A/syn.csv','--rate','100','--kind',kind,'--axes','gy,gz,ax','--threads','1','-q','-o',f'/tmp/probe_A/cli_{kind}.yaml'],capture_output=True)
    cli=open(f'/tmp/probe_A/cli_{kind}.yaml').read()
    open(f'/tmp/probe_A/py_{kind}.yaml','w').write(py)
    diff=[l for l in difflib.unified_diff(cli.splitlines(),py.splitlines(),lineterm='',n=0) if not l.startswith(('---','+++','@@'))]
    print(kind,'py warnings',len(wl),'diff lines',len(diff)); print('\n'.join(diff[:10]))
