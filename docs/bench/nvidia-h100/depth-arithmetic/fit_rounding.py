# The exact plane through the snapped vertices, rounded to float32 three ways, against the
# hardware's depth; per-vertex window depth in float32 (zw32), in float64 (zw64) or from NDC.
import collections, sys
import numpy as np
from probe_data import f32, ulpdiff, rounded as round_dir, covered_pixels, window_positions, snapped
d=sys.argv[1]
res=collections.defaultdict(collections.Counter); total=0
for b in range(8):
    c,px,py,D,_=covered_pixels(d,b); total+=len(D)
    ndc,win=window_positions(c)
    V=snapped(win)
    x0,y0=V[:,0,0],V[:,0,1];x1,y1=V[:,1,0],V[:,1,1];x2,y2=V[:,2,0],V[:,2,1]
    area=(x1-x0)*(y2-y0)-(x2-x0)*(y1-y0)
    e0=(x2-x1)*(py-y1)-(y2-y1)*(px-x1); e1=(x0-x2)*(py-y2)-(y0-y2)*(px-x2); e2=(x1-x0)*(py-y0)-(y1-y0)*(px-x0)
    zvars={'zw32':(ndc[:,:,2]*f32(0.5)+f32(0.5)).astype(f32).astype(np.float64),
           'zw64':c[:,:,2].astype(np.float64)/c[:,:,3].astype(np.float64)*0.5+0.5,
           'zndc32':ndc[:,:,2].astype(np.float64)}
    for zn,zw in zvars.items():
        z=(zw[:,0]*e0+zw[:,1]*e1+zw[:,2]*e2)/area
        if zn=='zndc32': z=z*0.5+0.5
        for mode in ('near','up','down'):
            res[(zn,mode)].update(np.clip(ulpdiff(D,round_dir(z,mode)),-5,5))
    # record worst cases for zw32 near
    if b==0:
        z=(zvars['zw32'][:,0]*e0+zvars['zw32'][:,1]*e1+zvars['zw32'][:,2]*e2)/area
        u=ulpdiff(D,round_dir(z,'up')); 
        print('example mismatches (up):', [(float(px[i]),float(py[i]),int(u[i]), float(D[i])) for i in np.nonzero(u)[0][:8]])
print('pixels',total)
for k,v in sorted(res.items(), key=lambda kv:-kv[1][0]):
    print('%-25s exact %.4f  '%(k,v[0]/total), ' '.join('%d:%.4f'%(u,v[u]/total) for u in sorted(v) if u!=0 and v[u]/total>1e-5))
