#!/usr/bin/env python3
"""The box scheme's positions (integrated along s) against its kinematics
(the velocities integrated in time), and the energy ledger with the gravity
energy of either. Usage: run bin/xcable on a case with &numerics scheme = 'box'
and &output interval = 0.002, energy = .true., then
    python3 positions_vs_kinematics.py results/<case>.h5
"""
import h5py, numpy as np, sys
h=h5py.File(sys.argv[1],'r'); t=h['time'][:]; x=h['x'][:]; z=h['z'][:]; u=h['u'][:]; v=h['v'][:]; s=h['s'][:]
st=h['static']; b0=st['beta0'][:]; b3=st['beta3'][:]
# need beta at each snapshot: derive tangent direction from u,v? we don't have beta. use geometric tangent from positions
tx=np.gradient(x,s,axis=1); tz=np.gradient(z,s,axis=1); n=np.hypot(tx,tz); tx/=n; tz/=n
vx=u*tx+v*tz; vz=u*tz-v*tx
dt=np.diff(t)[:,None]
zi=z[0]+np.vstack([np.zeros((1,len(s))),np.cumsum(0.5*(vz[1:]+vz[:-1])*dt,axis=0)])
w0=1140*np.pi*0.05**2/4*9.81
def trap(f): return np.sum(0.5*(f[:,1:]+f[:,:-1])*np.diff(s),axis=1)
Eg=w0*trap(z); Egi=w0*trap(zi)
ht=h['history/time'][:]; e=h['history/energy']
led=np.interp(t,ht,e['ledger'][:]); grav=np.interp(t,ht,e['gravity'][:])
for tt in [0.2,0.4,0.6,0.8,1.0]:
    i=np.searchsorted(t,tt-1e-9)
    print('t=%.2f ledger drift %+.1f  grav(s-int) %.1f  grav(t-int) %.1f  ledger with t-int grav %+.1f'%(t[i],led[i]-led[0],Eg[i],Egi[i],led[i]-grav[i]+Egi[i]-led[0]))
