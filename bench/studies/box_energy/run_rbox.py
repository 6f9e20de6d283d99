import numpy as np, sys, time
from rbox import *
from law import *
def static(sysm,Ts):
    n=sysm.n; s_=np.linspace(0,L,n)
    # catenary guess
    H=np.sqrt(Ts**2-(w0*L/2)**2); V=w0*(s_-L/2); T=np.hypot(H,V)
    e=np.array([finv(t) for t in T]); alpha=np.arctan2(H,V)
    om=-H*w0/T**2
    tx,tz=np.sin(alpha),np.cos(alpha)
    x=np.concatenate([[0],np.cumsum(0.5*((1+e[1:])*tx[1:]+(1+e[:-1])*tx[:-1])*sysm.ds)])
    z=np.concatenate([[0],np.cumsum(0.5*((1+e[1:])*tz[1:]+(1+e[:-1])*tz[:-1])*sysm.ds)])
    X=np.stack([e,0*e,alpha,om,x,z],1).ravel()
    X,it=newton(lambda X: sysm.res_static(X,Ts),X)
    return X
def energies(sysm,X,V):
    e,sn,phi,om,x,z=unpack(X,sysm.n); ds=sysm.ds
    tr=lambda q: ds*(np.sum(q)-0.5*(q[0]+q[-1]))
    return np.array([tr(W(e)), tr(0.5*m*(V[0]**2+V[1]**2)), tr(0.5*EI*om**2), tr(w0*z)])
def run(npn,Ts,tbr,tend,courant=1.0,p=1,dtfix=None,report=(0.1,0.2,0.3,0.5,0.7,1.0,1.5,2.0)):
    S=Sys(npn,p); X=static(S,Ts); n=npn
    e,sn,phi,om,x,z=unpack(X,n)
    Nx,Nz=S.nodeN(e[-1:],sn[-1:],phi[-1:]); F0=np.array([Nx[0],Nz[0]])
    cref=np.sqrt(fp(e[-1])/m); dt=dtfix or courant*S.ds/cref
    V=np.zeros((2,n)); t=0; Om0=om[0]; Om1=om[-1]
    E0=energies(S,X,V); work=0; led0=E0.sum()
    fac=lambda t: 1.0 if t<=0 else (0.0 if t>=tbr else np.cos(0.5*np.pi*t/tbr)**2)
    out=[]; rep=list(report); t0=time.time(); Vend_old=V[:,-1].copy()
    while t<tend-1e-12:
        Fn=F0*fac(t+dt); Fo=F0*fac(t)
        fun=lambda Xn: S.res_dyn(Xn,X,V,dt,Fn,Om0,Om1,Fo[0] if False else Ts,cref)[0]
        Xn,it=newton(fun,X.copy())
        _,Vn=S.res_dyn(Xn,X,V,dt,Fn,Om0,Om1,Ts,cref); Vn=np.array(Vn)
        work+=0.5*dt*(Fo@V[:,-1]+Fn@Vn[:,-1])
        X=Xn; V=Vn; t+=dt
        E=energies(S,X,V)
        if rep and t>=rep[0]-1e-9:
            rep.pop(0); e,sn,phi,om,x,z=unpack(X,n)
            out.append((t,E.sum()-work-led0,E,x[-1],z[-1],np.min(e)))
            print('  t=%.3f drift %+9.3f J  (S %.1f K %.1f B %.1f G %.1f) end (%.3f,%.3f) min eps %.3f  [%.0fs]'%(t,E.sum()-work-led0,*E,x[-1],z[-1],np.min(e),time.time()-t0),flush=True)
    return out
if __name__=='__main__':
    npn=int(sys.argv[1]); Ts=float(sys.argv[2]); tbr=float(sys.argv[3]); tend=float(sys.argv[4]); p=int(sys.argv[5]) if len(sys.argv)>5 else 1
    print('nodes',npn,'Ts',Ts,'tbr',tbr,'p',p, 'S0', None)
    run(npn,Ts,tbr,tend,p=p)
