# Prototype: positional box scheme (angle form), unknowns per node [eps, Sn, phi, Om, x, z]
import numpy as np, scipy.sparse as sp, scipy.sparse.linalg as sla, sys, time
from law import f, fp, W, finv
L=60.0; d=0.05; A=np.pi*d**2/4; rho=1140; m=rho*A; g=9.81; w0=m*g; EI=230e6*np.pi*d**4/64
NV=6
def tvec(phi): return np.sin(phi), np.cos(phi)          # (x,z) of t ; phi = paper alpha
def nvec(phi): return np.cos(phi), -np.sin(phi)
def unpack(X,np_): Y=X.reshape(np_,NV); return [Y[:,i] for i in range(NV)]
class Sys:
    def __init__(s,npn,moment_pow=1, avg='corner'):
        s.n=npn; s.ds=L/(npn-1); s.p=moment_pow; s.avg=avg
    def nodeN(s,e,sn,phi):
        tx,tz=tvec(phi); nx,nz=nvec(phi); T=f(e)
        return T*tx+sn*nx, T*tz+sn*nz
    def stretch(s,e,phi):
        tx,tz=tvec(phi); return (1+e)*tx,(1+e)*tz
    def res_static(s,X,Ts):
        e,sn,phi,om,x,z=unpack(X,s.n); ds=s.ds
        Nx,Nz=s.nodeN(e,sn,phi); sx,sz=s.stretch(e,phi)
        r=[]
        r+= [x[0]/L, z[0]/L, (f(e[0])-Ts)/Ts, sn[0]/Ts]
        a=lambda q:0.5*(q[1:]+q[:-1]); D=lambda q:(q[1:]-q[:-1])/ds
        R=np.zeros((s.n-1,NV))
        R[:,0]=D(Nx)/Ts; R[:,1]=(D(Nz)-w0)/Ts
        R[:,2]=D(x)-a(sx); R[:,3]=D(z)-a(sz)
        R[:,4]=(D(phi)-a(om))*L; R[:,5]=(EI*D(om)+a((1+e)**s.p*sn))/Ts
        r2=[(f(e[-1])-Ts)/Ts, sn[-1]/Ts]
        return np.concatenate([r,R.ravel(),r2])
    def res_dyn(s,X,Xo,Vo,dt,F,Om0,Om1,Ts,cref):
        # X new, Xo old unknowns; Vo old nodal velocities (2,n)
        e,sn,phi,om,x,z=unpack(X,s.n); eo,sno,phio,omo,xo,zo=unpack(Xo,s.n); ds=s.ds
        Vx=2*(x-xo)/dt-Vo[0]; Vz=2*(z-zo)/dt-Vo[1]
        Nx,Nz=s.nodeN(e,sn,phi); Nxo,Nzo=s.nodeN(eo,sno,phio)
        sx,sz=s.stretch(e,phi); sxo,szo=s.stretch(eo,phio)
        a=lambda q:0.5*(q[1:]+q[:-1]); D=lambda q:(q[1:]-q[:-1])/ds
        R=np.zeros((s.n-1,NV))
        R[:,0]=(m*(a(Vx)-a(Vo[0]))/dt - 0.5*(D(Nx)+D(Nxo)))/Ts
        R[:,1]=(m*(a(Vz)-a(Vo[1]))/dt - 0.5*(D(Nz)+D(Nzo)) + w0)/Ts
        R[:,2]=0.5*(D(x)+D(xo)) - 0.5*(a(sx)+a(sxo))
        R[:,3]=0.5*(D(z)+D(zo)) - 0.5*(a(sz)+a(szo))
        R[:,4]=(0.5*(D(phi)+D(phio)) - 0.5*(a(om)+a(omo)))*L
        R[:,5]=(EI*0.5*(D(om)+D(omo)) + 0.5*(a((1+e)**s.p*sn)+a((1+eo)**s.p*sno)))/Ts
        r1=[Vx[0]/cref, Vz[0]/cref, (om[0]-Om0)*L]
        r2=[(Nx[-1]-F[0])/Ts, (Nz[-1]-F[1])/Ts, (om[-1]-Om1)*L]
        return np.concatenate([r1,R.ravel(),r2]), (Vx,Vz)

def fdjac(fun,X,bw=2*NV+6):
    n=len(X); r0=fun(X); rows=[];cols=[];vals=[]
    ncol=2*bw+1
    for c in range(ncol):
        idx=np.arange(c,n,ncol); h=1e-7*np.maximum(1,np.abs(X[idx]))
        Xp=X.copy(); Xp[idx]+=h; Xm=X.copy(); Xm[idx]-=h
        dr=(fun(Xp)-fun(Xm))
        for j,hj in zip(idx,h):
            lo=max(0,j-bw); hi=min(n,j+bw+1)
            col=dr[lo:hi]/(2*hj); nz=np.nonzero(col)[0]
            rows+=list(lo+nz); cols+=[j]*len(nz); vals+=list(col[nz])
    return sp.csc_matrix((vals,(rows,cols)),shape=(n,n)), r0

def newton(fun,X,tol=1e-11,maxit=30):
    for it in range(maxit):
        J,r=fdjac(fun,X); dx=sla.spsolve(J,r); X=X-dx
        if np.max(np.abs(dx))<tol: return X,it+1
    raise RuntimeError('newton fail %g'%np.max(np.abs(dx)))
