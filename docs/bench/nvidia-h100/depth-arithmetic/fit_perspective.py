# Depth by perspective-correct interpolation of clip z and w, by NDC z interpolated then mapped
# to the window, by 1 - z, and by float32 barycentrics summed in order.
import collections, sys
import numpy as np
from probe_data import f32, ulpdiff, rounded, covered_pixels, window_positions, snapped
d=sys.argv[1]
res=collections.defaultdict(collections.Counter); total=0
for b in range(3):
    c,px,py,D,_=covered_pixels(d,b); total+=len(D)
    ndc,win=window_positions(c); V=snapped(win)
    x=V[:,:,0]; y=V[:,:,1]
    e0=(x[:,2]-x[:,1])*(py-y[:,1])-(y[:,2]-y[:,1])*(px-x[:,1])
    e1=(x[:,0]-x[:,2])*(py-y[:,2])-(y[:,0]-y[:,2])*(px-x[:,2])
    e2=(x[:,1]-x[:,0])*(py-y[:,0])-(y[:,1]-y[:,0])*(px-x[:,0])
    E=np.stack([e0,e1,e2],1); bsum=E.sum(1,keepdims=True); bary=E/bsum
    zc=c[:,:,2].astype(np.float64); wc=c[:,:,3].astype(np.float64)
    # perspective-correct in float64, rounded
    lam=bary/wc; znd=(lam*zc).sum(1)/(lam*wc).sum(1)
    for m in ('near','down','trunc','up'):
        res[('persp64',m)].update(np.clip(ulpdiff(D,rounded(znd*0.5+0.5,m)),-3,3))
    # z_ndc interpolated linearly from per-vertex float32 ndc z, then *0.5+0.5 in float32
    zn=ndc[:,:,2].astype(np.float64); lin=(bary*zn).sum(1)
    for m in ('near','down','trunc'):
        l32=rounded(lin,m)
        res[('ndc-linear-then-window',m)].update(np.clip(ulpdiff(D,(l32*f32(0.5)+f32(0.5)).astype(f32)),-3,3))
    # 1-z representation: interpolate (1 - zw) exactly then 1 - that
    zw=(ndc[:,:,2]*f32(0.5)+f32(0.5)).astype(f32).astype(np.float64)
    one_minus=(bary*(1.0-zw)).sum(1)
    for m in ('near','down','up','trunc'):
        om=rounded(one_minus,m).astype(np.float64)
        res[('one-minus',m)].update(np.clip(ulpdiff(D,rounded(1.0-om,'near')),-3,3))
    # barycentrics rounded to float32 first, then float32 sum in fixed order
    b32=bary.astype(f32)
    z32=(b32[:,0]*zw[:,0].astype(f32)).astype(f32); z32=(z32+(b32[:,1]*zw[:,1].astype(f32)).astype(f32)).astype(f32); z32=(z32+(b32[:,2]*zw[:,2].astype(f32)).astype(f32)).astype(f32)
    res[('bary32-sum',)].update(np.clip(ulpdiff(D,z32),-3,3))
print('pixels',total)
for k,v in sorted(res.items(), key=lambda kv:-kv[1][0]):
    print('%-40s exact %.4f  '%(str(k),v[0]/total), ' '.join('%d:%.4f'%(u,v[u]/total) for u in sorted(v) if u!=0 and v[u]/total>1e-4))
