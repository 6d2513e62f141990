import sys,re,numpy as np
sys.path.insert(0,'/tmp/probe_A'); from util import burg
s=np.load('/tmp/probe_A/syn.npz')
# use file-rounded values
X=np.loadtxt('/tmp/probe_A/syn.csv',delimiter=',',skiprows=1)
txt=open(sys.argv[1]).read()
for ch,col,p in [('y',1,2),('z',2,5)]:
    a,E,k=burg(X[:,col],p)
    blk=txt.split(f'  {ch}:')[1]
    m=re.search(r'a: \[([^\]]*)\], sigma: ([\d.eE+-]+) deg/s',blk)
    at=np.array([float(v) for v in m.group(1).split(',')]); sg=float(m.group(2))
    Et=float(re.search(r'E = ([\d.eE+-]+)',blk).group(1))
    print(ch,'a mine',a[1:],'\n  tool',at,'\n  max|da|',np.max(np.abs(a[1:]-at)),'sigma mine deg/s',np.degrees(np.sqrt(E)),'tool',sg,'E',E,Et)
    # MDL check
    N=len(X); Es=[np.mean((X[:,col]-X[:,col].mean())**2)]
    for q in range(1,21): Es.append(burg(X[:,col],q)[1])
    Es=np.array(Es); ps=np.arange(21)
    print('  MDL',np.argmin(N*np.log(Es)+ps*np.log(N)),'AIC',np.argmin(N*np.log(Es)+2*ps),'FPE',np.argmin(Es*(N+ps+1)/(N-ps-1)))
