import numpy as np,glob
K=30*np.pi/180/3600/60; N=0.3*np.pi/180/60
d=[]
for f in sorted(glob.glob('rec10_T_*.csv'))[:100]:
    x=np.loadtxt(f,delimiter=',',skiprows=1,usecols=(1,2,3))
    a=x[:6000].mean(0); b=x[-6000:].mean(0); d.append(b-a)
d=np.array(d); n=d.size
exp=K**2*(540-40)+2*N**2/60
print("files",len(d),"var(last60-first60)/theory per axis",(d**2).mean(0)/exp,"all",(d**2).mean()/exp,"99pct +-", round(2.58*np.sqrt(2/n),2))
