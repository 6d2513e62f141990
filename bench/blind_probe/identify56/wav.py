import numpy as np
from math import comb
def db_rec_lo(N):
    # Daubechies minimum-phase scaling filter via spectral factorization
    # P(y)=sum C(N-1+k,k) y^k, y=(2-z-1/z)/4 ; roots in y, map to z
    P=[comb(N-1+k,k) for k in range(N)]
    yr=np.roots(P[::-1])
    zs=[]
    for y in yr:
        # y=(2-z-1/z)/4 -> z^2 + (4y-2) z + 1 = 0
        r=np.roots([1,4*y-2,1]); zs.append(r[np.argmin(np.abs(r))])
    h=np.poly1d([1.0])
    for _ in range(N): h=h*np.poly1d([1,1])
    for z in zs: h=h*np.poly1d([1,-z])
    c=np.real(h.c); c=c/np.sum(c)*np.sqrt(2)
    return c
rec_lo=db_rec_lo(5)
known=np.array([0.16010239797419293,0.6038292697971896,0.7243085284377729,0.13842814590132074,-0.24229488706638203,-0.032244869584638375,0.07757149384004572,-0.006241490212798274,-0.012580751999081999,0.0033357252854737712])
if abs(rec_lo[0])<0.01: rec_lo=rec_lo[::-1]
assert np.max(np.abs(rec_lo-known))<1e-10, (rec_lo,known)
F=10
dec_lo=rec_lo[::-1]
dec_hi=np.array([(-1)**(k+1)*rec_lo[k] for k in range(F)])
rec_hi=dec_hi[::-1]
def ext(x,n):
    # half-sample symmetric extension by n each side
    left=x[:n][::-1]; right=x[-n:][::-1]
    while len(left)<n: left=np.r_[x[::-1] if False else left, left]  # not needed for long x
    return np.r_[left,x,right]
def dwt(x):
    N=len(x); xe=ext(x,F-1)  # xe[i+F-1]=x[i]
    full=np.convolve(xe,dec_lo)  # full[m]=sum_j h[j] xe[m-j]
    fullh=np.convolve(xe,dec_hi)
    # want out[k]=sum_j h[j] x[i-j], i=2k+1 -> xe index i+F-1
    idx=np.arange(1,N+F-1,2)+F-1
    return full[idx],fullh[idx]
def idwt(a,d):
    n=len(a); up_a=np.zeros(2*n); up_a[::2]=a; up_d=np.zeros(2*n); up_d[::2]=d
    y=np.convolve(up_a,rec_lo)+np.convolve(up_d,rec_hi)
    L=2*n-F+2
    return y[F-2:F-2+L]
def maxlev(N): return int(np.floor(np.log2(N/(F-1))))
def wavedec(x,lev):
    cs=[]; a=x
    for _ in range(lev):
        a,d=dwt(a); cs.append(d)
    return a,cs[::-1]
def waverec(a,ds):
    for d in ds:
        if len(a)==len(d)+1: a=a[:-1]
        a=idwt(a,d)
    return a
def denoise(x,mode='soft'):
    lev=maxlev(len(x)); a,ds=wavedec(x,lev)
    sig=np.median(np.abs(ds[-1]))/0.6744897501960817
    thr=sig*np.sqrt(2*np.log(len(x)))
    if mode=='soft': ds=[np.sign(d)*np.maximum(np.abs(d)-thr,0) for d in ds]
    else: ds=[d*(np.abs(d)>thr) for d in ds]
    y=waverec(a,ds)[:len(x)]
    return y,sig,thr,lev
if __name__=='__main__':
    x=np.random.default_rng(0).standard_normal(1001)
    a,ds=wavedec(x,maxlev(1001)); print('PR err',np.max(np.abs(waverec(a,ds)[:1001]-x)))
