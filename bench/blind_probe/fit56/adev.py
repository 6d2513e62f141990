import numpy as np
def oadev(y, dt, ms):
    c = np.concatenate([[0], np.cumsum(y)])*dt; n=len(y); out=[]
    for m in ms:
        d = c[2*m:] - 2*c[m:n-m+1] + c[:n-2*m+1]
        out.append(np.sqrt(np.mean(d**2)/(2*(m*dt)**2)))
    return np.array(out)
