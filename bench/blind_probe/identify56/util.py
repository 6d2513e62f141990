import numpy as np
def lfilter_ar(a, e):
    # x[n] = e[n] - sum a[i] x[n-i], a[0]=1
    p=len(a)-1; x=np.zeros(len(e)); a=np.asarray(a,float)
    for n in range(len(e)):
        s=e[n]
        for i in range(1,p+1):
            if n-i>=0: s-=a[i]*x[n-i]
        x[n]=s
    return x
def oavar(y, m):
    # overlapping Allan variance of rate samples y at averaging factor m
    N=len(y); x=np.concatenate([[0],np.cumsum(y)])  # phase in units of sample*rate
    d=x[2*m:]-2*x[m:-m]+x[:-2*m]
    return np.mean(d**2)/(2*m*m), len(d)
def welch(x, fs, nseg):
    n=np.arange(nseg); w=0.5-0.5*np.cos(2*np.pi*n/nseg)  # periodic hann
    step=nseg//2; segs=[]
    for s in range(0,len(x)-nseg+1,step):
        seg=x[s:s+nseg]; seg=seg-seg.mean()
        X=np.fft.rfft(seg*w); segs.append(np.abs(X)**2)
    P=np.mean(segs,axis=0)/(fs*np.sum(w**2))
    if nseg%2==0: P[1:-1]*=2
    else: P[1:]*=2
    return np.fft.rfftfreq(nseg,1/fs), P
def acf_biased(x, maxlag):
    x=x-x.mean(); N=len(x); n=1<<int(np.ceil(np.log2(N+maxlag+1)))
    X=np.fft.rfft(x,n); r=np.fft.irfft(np.abs(X)**2,n)[:maxlag+1]/N
    return r
def burg(x, p, demean=True):
    x=np.asarray(x,float)
    if demean: x=x-x.mean()
    N=len(x); f=x.copy(); b=x.copy(); a=np.array([1.0]); E=np.dot(x,x)/N; ks=[]
    for m in range(1,p+1):
        ff=f[m:]; bb=b[m-1:N-1]
        k=-2*np.dot(ff,bb)/(np.dot(ff,ff)+np.dot(bb,bb))
        ks.append(k)
        fn=ff+k*bb; bn=bb+k*ff
        f[m:]=fn; b[m:]=bn
        a=np.concatenate([a,[0]]); a=a+k*a[::-1]
        E*=(1-k*k)
    return a,E,np.array(ks)
