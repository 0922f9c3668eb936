#!/usr/bin/python3
"""A 1D Godunov reference for uniaxial.py: MUSCL with RK2 and an acoustic
Riemann flux on the same bounce (L = c = Z = 1, contact at t = 0.5, CFL 0.3),
the wall a mirror cell once the end reaches it, the free end a mirror of
the opposite sign.  The wall holds the end once touched (it does not
release it): the values up to the separation (t = 2.5) compare with
uniaxial.py's, the one at t = 3.0 is a clamped bar's.

    /usr/bin/python3 godunov1D.py LIMITERS [RK order]

LIMITERS: comma-separated of fo, minmod, mc, vanleer, superbee, none, and
kX (slope min(2 min(a, b), X (a + b)/2): mc is k1), koren (third order,
kappa = 1/3, face increments min(2 b, (a + 2 b)/3, 2 a)/2 and its mirror)
and korenX (X instead of 2); A>B takes each step
with A and, when that step would raise the energy, again with B (the
energy then never grows).  Prints per limiter, N
(25, 50, 100) and limited variables (char: the characteristic variables
s -+ Z v; cons: v and s) E/E0 at t = 0.625, 1.5, 2.5 (separation) and 3.0,
the largest rise of the energy in a step (/E0) and, with A>B, the number
of steps taken with B.
Not a model of touchFoam's compatible update: a reference for what the
limiter alone does to a front in a plain finite-volume scheme.
"""
import numpy as np, sys
# 1D linear acoustics: rho v_t = s_x, s_t = E v_x (s stress, tension +), Z = sqrt(rho E), c = sqrt(E/rho)
# bar [0,1], wall at x=0 (v=0 while s<0 ... contact: v_wall=0 when compressive), free end at x=1 (s=0).
rho=1.0; E=1.0; c=1.0; Z=1.0
def lim(a,b,kind):
    if kind=='none': return 0.5*(a+b)
    if kind=='fo': return 0*a
    s=np.sign(a); same=(a*b>0)
    a_,b_=np.abs(a),np.abs(b)
    if kind=='minmod': r=np.minimum(a_,b_)
    elif kind=='mc': r=np.minimum(np.minimum(2*a_,2*b_),0.5*(a_+b_))
    elif kind=='superbee': r=np.maximum(np.minimum(2*a_,b_),np.minimum(a_,2*b_))
    elif kind.startswith('k'):
        k=float(kind[1:]); r=np.minimum(np.minimum(2*a_,2*b_),k*0.5*(a_+b_))
    elif kind=='vanleer': r=2*a_*b_/(a_+b_+1e-300)
    return np.where(same,s*r,0.0)
def run(N,kind,cfl=0.3,rk=2,char=True,v0=1.0,T=3.0,gap_t=0.5):
    h=1.0/N; dt=cfl*h/c
    v=-v0*np.ones(N); s=np.zeros(N)
    t=0; xw=gap_t*v0  # wall position -gap ... bar end position x_end = -v0 t ; contact when x_end<= -gap
    E0=0.5*rho*v0**2
    def energy(v,s): return np.sum(0.5*rho*v**2+0.5*s**2/E)*h
    def rates(v,s,t,D):
        # ghost cells: free end: reflect s-> -s, v->v ; wall: depends on contact
        # contact decided by displacement of the end D
        incontact = D<=-gap_t*v0+1e-14
        # pad
        if incontact:
            vg0,sg0=-v[0],s[0]   # mirror: v->-v, s->s
        else:
            vg0,sg0=v[0],-s[0]
        V=np.concatenate(([vg0],v,[v[-1]])); S=np.concatenate(([sg0],s,[-s[-1]]))
        if use[0].startswith('koren'):
            # third order (kappa = 1/3) with the Koren limiter: separate
            # increments to the right and left faces
            c=float(use[0][5:]) if len(use[0])>5 else 2.0
            def kor(Q):
                a=Q[1:-1]-Q[:-2]; b=Q[2:]-Q[1:-1]; same=a*b>0; sg=np.sign(a)
                A,B=np.abs(a),np.abs(b)
                up=np.where(same,sg*0.5*np.minimum(np.minimum(c*B,(A+2*B)/3),c*A),0)
                dn=np.where(same,sg*0.5*np.minimum(np.minimum(c*A,(B+2*A)/3),c*B),0)
                return up,dn
            if char:
                u1,d1=kor(S-Z*V); u2,d2=kor(S+Z*V)
                uV,dVn=(u2-u1)/(2*Z),(d2-d1)/(2*Z); uS,dSn=(u1+u2)/2,(d1+d2)/2
            else:
                uV,dVn=kor(V); uS,dSn=kor(S)
        elif char:
            W1=S-Z*V; W2=S+Z*V
            dW1=lim(W1[1:-1]-W1[:-2],W1[2:]-W1[1:-1],use[0]); dW2=lim(W2[1:-1]-W2[:-2],W2[2:]-W2[1:-1],use[0])
            dV=(dW2-dW1)/(2*Z); dS=(dW1+dW2)/2
        else:
            dV=lim(V[1:-1]-V[:-2],V[2:]-V[1:-1],use[0]); dS=lim(S[1:-1]-S[:-2],S[2:]-S[1:-1],use[0])
        if not use[0].startswith('koren'):
            uV=dVn=0.5*dV; uS=dSn=0.5*dS
        # face values: left/right states at faces 0..N
        VL=np.concatenate(([vg0],v+uV)); SL=np.concatenate(([sg0],s+uS))
        VR=np.concatenate((v-dVn,[v[-1]])); SR=np.concatenate((s-dSn,[-s[-1]]))
        # boundary faces: wall face 0, free face N: use mirror of reconstructed
        VL[0]=(-VR[0] if incontact else VR[0]); SL[0]=(SR[0] if incontact else -SR[0])
        VR[-1]=VL[-1]; SR[-1]=-SL[-1]
        vs=0.5*(VL+VR)+(SR-SL)/(2*Z); ss=0.5*(SL+SR)+Z*(VR-VL)/2
        return (ss[1:]-ss[:-1])/(rho*h),(E*(vs[1:]-vs[:-1])/h), vs[0]
    D=0.0; hist=[]; use=[None]; fallbacks=0
    choices=kind.split('>')
    while t<T-1e-12:
        k=min(dt,T-t)
        v0_,s0_,D0=v.copy(),s.copy(),D
        Eold=energy(v0_,s0_)
        for choice in choices:
            use[0]=choice
            v,s,D=v0_.copy(),s0_.copy(),D0
            if rk==1:
                a,b,w=rates(v,s,t,D); v=v+k*a; s=s+k*b; D=D+k*w
            elif rk==2:
                a,b,w=rates(v,s,t,D); v1=v+k*a; s1=s+k*b; D1=D+k*w
                a,b,w=rates(v1,s1,t,D1); v=0.5*(v0_+v1+k*a); s=0.5*(s0_+s1+k*b); D=0.5*(D0+D1+k*w)
            else:
                a,b,w=rates(v,s,t,D); v1=v+k*a; s1=s+k*b; D1=D+k*w
                a,b,w=rates(v1,s1,t,D1); v2=0.75*v0_+0.25*(v1+k*a); s2=0.75*s0_+0.25*(s1+k*b); D2=0.75*D0+0.25*(D1+k*w)
                a,b,w=rates(v2,s2,t,D2); v=v0_/3+2/3*(v2+k*a); s=s0_/3+2/3*(s2+k*b); D=D0/3+2/3*(D2+k*w)
            if energy(v,s)<=Eold*(1+1e-14):
                break
        if use[0]!=choices[0]:
            fallbacks+=1
        t+=k; hist.append((t,energy(v,s)/E0))
    hist=np.array(hist)
    g=[0.625,1.5,2.5,3.0]
    rise=max(0.0,np.diff(hist[:,1]).max())
    return [np.interp(x,hist[:,0],hist[:,1]) for x in g]+[rise,fallbacks]
for kind in sys.argv[1].split(','):
  for N in [25,50,100]:
    for ch in [True,False]:
      e=run(N,kind,char=ch,rk=int(sys.argv[2]) if len(sys.argv)>2 else 2)
      print(kind,N,'char' if ch else 'cons',' '.join('%.4f'%x for x in e[:4]),
            'rise %.1e'%e[4],'fallbacks %d'%e[5])
