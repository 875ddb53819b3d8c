# Planes evaluated from a tile origin (T = 1..32 pixels): the origin value rounded three ways,
# then the gradients times the offset, in one rounding.
import collections, sys
import numpy as np
from probe_data import f32, ulpdiff, rounded, covered_pixels, window_positions, snapped
d=sys.argv[1]
res=collections.defaultdict(collections.Counter); total=0
for b in range(3):
    c,px,py,D,_=covered_pixels(d,b); total+=len(D)
    ndc,win=window_positions(c); V=snapped(win)
    zw=(ndc[:,:,2]*f32(0.5)+f32(0.5)).astype(f32).astype(np.float64)
    x=V[:,:,0]; y=V[:,:,1]
    area=(x[:,1]-x[:,0])*(y[:,2]-y[:,0])-(x[:,2]-x[:,0])*(y[:,1]-y[:,0])
    A=((zw[:,1]-zw[:,0])*(y[:,2]-y[:,0])-(zw[:,2]-zw[:,0])*(y[:,1]-y[:,0]))/area
    B=((zw[:,2]-zw[:,0])*(x[:,1]-x[:,0])-(zw[:,1]-zw[:,0])*(x[:,2]-x[:,0]))/area
    def plane(X,Y): return zw[:,0]+A*(X-x[:,0])+B*(Y-y[:,0])
    for T in (1,2,4,8,16,32):
        tx=np.floor((px-0.5)/T)*T; ty=np.floor((py-0.5)/T)*T
        for om in ('near','down','trunc'):
            zt=rounded(plane(tx,ty),om).astype(np.float64)
            for gm in ('near','trunc','down'):
                Ag=rounded(A,gm).astype(np.float64); Bg=rounded(B,gm).astype(np.float64)
                for em in ('near','down','trunc'):
                    z=rounded(zt+Ag*(px-tx)+Bg*(py-ty),em)
                    res[(T,'origin-'+om,'grad-'+gm,'fused-'+em)].update(np.clip(ulpdiff(D,z),-3,3))
                    # sample offsets relative to tile centre
print('pixels',total)
for k,v in sorted(res.items(), key=lambda kv:-kv[1][0])[:12]:
    print('%-50s exact %.4f  '%(str(k),v[0]/total), ' '.join('%d:%.4f'%(u,v[u]/total) for u in sorted(v) if u!=0 and v[u]/total>1e-4))
