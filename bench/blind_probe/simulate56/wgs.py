import mpmath as mp, numpy as np
mp.mp.dps = 40
a = mp.mpf(6378137); f = 1/mp.mpf('298.257223563'); GM = mp.mpf('3.986004418e14'); W = mp.mpf('7.292115e-5')
b = a*(1-f); E = mp.sqrt(a*a-b*b); e2 = f*(2-f)
def q(u): return ((1+3*u*u/E**2)*mp.atan(E/u) - 3*u/E)/2
q0 = q(b)
def U(x,y,z):
    p2 = x*x+y*y; r2 = p2+z*z
    d = r2-E*E
    u2 = d/2*(1+mp.sqrt(1+4*E*E*z*z/d**2)); u = mp.sqrt(u2)
    # sin beta
    p = mp.sqrt(p2)
    beta = mp.atan2(z*mp.sqrt(u2+E*E), u*p)
    return GM/E*mp.atan(E/u) + W**2*a*a/2*q(u)/q0*(mp.sin(beta)**2-mp.mpf(1)/3) + W**2/2*(u2+E*E)*mp.cos(beta)**2
def ecef(lat,lon,h):
    lat=mp.mpf(lat);lon=mp.mpf(lon);h=mp.mpf(h)
    N = a/mp.sqrt(1-e2*mp.sin(lat)**2)
    return ((N+h)*mp.cos(lat)*mp.cos(lon),(N+h)*mp.cos(lat)*mp.sin(lon),(N*(1-e2)+h)*mp.sin(lat))
def gravity_ned(latdeg,h,lon=0):
    lat = mp.radians(latdeg); lo = mp.radians(lon)
    X = ecef(lat,lo,h); s = mp.mpf('0.01')
    g = []
    for i in range(3):
        def Ui(dd):
            Y=list(X); Y[i]+=dd; return U(*Y)
        g.append((-Ui(2*s)+8*Ui(s)-8*Ui(-s)+Ui(-2*s))/(12*s))
    g = mp.matrix(g)
    sl,cl,so,co = mp.sin(lat),mp.cos(lat),mp.sin(lo),mp.cos(lo)
    Cen = mp.matrix([[-sl*co,-sl*so,cl],[-so,co,0],[-cl*co,-cl*so,-sl]])
    gn = Cen*g
    return np.array([float(gn[i]) for i in range(3)])
WE = 7.292115e-5
A=6378137.0; F=1/298.257223563; E2=F*(2-F)
def radii(lat):
    s=np.sin(lat); w=1-E2*s*s
    return A*(1-E2)/w**1.5, A/np.sqrt(w)
def Cnb(r,p,y):
    cr,sr,cp,sp,cy,sy=np.cos(r),np.sin(r),np.cos(p),np.sin(p),np.cos(y),np.sin(y)
    return np.array([[cp*cy, sr*sp*cy-cr*sy, cr*sp*cy+sr*sy],[cp*sy, sr*sp*sy+cr*cy, cr*sp*sy-sr*cy],[-sp, sr*cp, cr*cp]])
def somigliana(latdeg,h):
    L=np.radians(latdeg); s2=np.sin(L)**2
    ge=9.7803253359; k=0.00193185265241; m=0.00344978650684
    g0=ge*(1+k*s2)/np.sqrt(1-E2*s2)
    return g0*(1-2/A*(1+F+m-2*F*s2)*h+3*h*h/A**2)
