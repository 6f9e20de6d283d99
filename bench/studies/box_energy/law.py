import numpy as np
P=[2.703e5,10.2,-2.128,2.627e5,135.5]
def f(e): return P[0]*np.tanh(P[1]*e+P[2])+P[3]+P[4]*e
def fp(e): return P[0]*P[1]/np.cosh(P[1]*e+P[2])**2+P[4]
def logcosh(x): return np.abs(x)+np.log1p(np.exp(-2*np.abs(x)))-np.log(2)
def W(e): return P[0]/P[1]*(logcosh(P[1]*e+P[2])-logcosh(P[2]))+P[3]*e+0.5*P[4]*e**2
def finv(T):
    from scipy.optimize import brentq
    return brentq(lambda e: f(e)-T, -0.99, 2.0, xtol=1e-15)
