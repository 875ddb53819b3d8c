# 72 float32 plane-equation forms against the hardware's depth: gradients rounded to nearest,
# down or truncated; the reference vertex; fused or separate evaluation in each rounding.
import collections, sys
import numpy as np
from probe_data import f32, ulpdiff, rounded as rnd, covered_pixels, window_positions, snapped
d=sys.argv[1]
res=collections.defaultdict(collections.Counter); total=0
for b in range(4):
    c,px,py,D,_=covered_pixels(d,b); total+=len(D)
    ndc,win=window_positions(c)
    V=snapped(win)
    zw=(ndc[:,:,2]*f32(0.5)+f32(0.5)).astype(f32).astype(np.float64)
    x=V[:,:,0]; y=V[:,:,1]
    area=(x[:,1]-x[:,0])*(y[:,2]-y[:,0])-(x[:,2]-x[:,0])*(y[:,1]-y[:,0])
    A=((zw[:,1]-zw[:,0])*(y[:,2]-y[:,0])-(zw[:,2]-zw[:,0])*(y[:,1]-y[:,0]))/area
    B=((zw[:,2]-zw[:,0])*(x[:,1]-x[:,0])-(zw[:,1]-zw[:,0])*(x[:,2]-x[:,0]))/area
    n=len(D); ar=np.arange(n)
    refs={'v0':np.zeros(n,int),'v1':np.ones(n,int),'v2':np.full(n,2),
          'minz':np.argmin(zw,1),'maxz':np.argmax(zw,1),'topleft':np.lexsort((x.T,-y.T))[0] if False else np.argmin(x*1e6-y,1)}
    for gm in ('near','down','trunc'):
        Ag,Bg=rnd(A,gm).astype(np.float64),rnd(B,gm).astype(np.float64)
        for rn,ri in refs.items():
            xr,yr,zr=x[ar,ri],y[ar,ri],zw[ar,ri]
            dx,dy=px-xr,py-yr
            for em in ('near','down','trunc'):
                # fused: one rounding of exact sum
                zf=rnd(zr+Ag*dx+Bg*dy,em)
                res[('grad-'+gm,rn,'fused-'+em)].update(np.clip(ulpdiff(D,zf),-3,3))
                # two fmas: fma(A,dx,fma(B,dy,zr))
                t1=rnd(Bg*dy+zr,em).astype(np.float64); zf2=rnd(Ag*dx+t1,em)
                res[('grad-'+gm,rn,'fma2-'+em)].update(np.clip(ulpdiff(D,zf2),-3,3))
                t1=rnd(Ag*dx+zr,em).astype(np.float64); zf2=rnd(Bg*dy+t1,em)
                res[('grad-'+gm,rn,'fma2x-'+em)].update(np.clip(ulpdiff(D,zf2),-3,3))
                # sum of products first then add z
                s=rnd(Ag*dx+Bg*dy,em).astype(np.float64); zf3=rnd(zr+s,em)
                res[('grad-'+gm,rn,'dot-then-z-'+em)].update(np.clip(ulpdiff(D,zf3),-3,3))
        # origin-based
        C=zw[:,0]-A*x[:,0]-B*y[:,0]
        for cm in ('near','down'):
            Cr=rnd(C,cm).astype(np.float64)
            for em in ('near','down','trunc'):
                res[('grad-'+gm,'origin-C'+cm,'fused-'+em)].update(np.clip(ulpdiff(D,rnd(Cr+Ag*px+Bg*py,em)),-3,3))
print('pixels',total)
for k,v in sorted(res.items(), key=lambda kv:-kv[1][0])[:15]:
    print('%-50s exact %.4f  '%(str(k),v[0]/total), ' '.join('%d:%.4f'%(u,v[u]/total) for u in sorted(v) if u!=0 and v[u]/total>1e-5))
