# The hardware's depth against the exact plane and float32 forms, through snapped or raw
# vertices, NDC by division or by a reciprocal; and gl_FragCoord.z against the depth buffer.
import collections, sys
import numpy as np
from probe_data import f32, ulpdiff, covered_pixels, window_positions
d=sys.argv[1]
res=collections.defaultdict(lambda: collections.Counter()); total=0
fz_eq=0
for b in range(8):
    c,px,py,D,FZ=covered_pixels(d,b); total+=len(D); fz_eq+=(FZ.view(np.uint32)==D.view(np.uint32)).sum()
    for divname in ('div','rcp'):
        ndc,win=window_positions(c,divname)
        zw=(ndc[:,:,2]*f32(0.5)+f32(0.5)).astype(f32)
        sn=np.round(win.astype(np.float64)*256)  # roundEven via np.round (banker's)
        for snapname,V in (('snap',sn/256.0),('raw',win.astype(np.float64))):
            x0,y0=V[:,0,0],V[:,0,1];x1,y1=V[:,1,0],V[:,1,1];x2,y2=V[:,2,0],V[:,2,1]
            z0,z1,z2=[zw[:,k].astype(np.float64) for k in range(3)]
            area=(x1-x0)*(y2-y0)-(x2-x0)*(y1-y0)
            # exact (double) plane at pixel centre
            e0=(x2-x1)*(py-y1)-(y2-y1)*(px-x1); e1=(x0-x2)*(py-y2)-(y0-y2)*(px-x2); e2=(x1-x0)*(py-y0)-(y1-y0)*(px-x0)
            zex=(z0*e0+z1*e1+z2*e2)/area
            res[(divname,snapname,'exact64')].update(np.clip(ulpdiff(D,zex.astype(f32)),-5,5))
            # current compute formula in float32
            E0,E1,E2=[e.astype(f32) for e in (e0,e1,e2)]
            inv=(f32(1)/(E0+E1+E2).astype(f32)).astype(f32)
            Z0,Z1,Z2=[z.astype(f32) for z in (z0,z1,z2)]
            cur=(Z0+((E1*inv).astype(f32)*(Z1-Z0).astype(f32)).astype(f32)).astype(f32)
            cur=(cur+((E2*inv).astype(f32)*(Z2-Z0).astype(f32)).astype(f32)).astype(f32)
            res[(divname,snapname,'current')].update(np.clip(ulpdiff(D,cur),-5,5))
            # float32 plane gradients, z = z0 + A*(px-x0) + B*(py-y0)
            A=((z1-z0)*(y2-y0)-(z2-z0)*(y1-y0))/area; Bc=((z2-z0)*(x1-x0)-(z1-z0)*(x2-x0))/area
            A32,B32=A.astype(f32),Bc.astype(f32)
            dx=(px-x0).astype(f32); dy=(py-y0).astype(f32)
            pl=(Z0+(A32*dx).astype(f32)).astype(f32); pl=(pl+(B32*dy).astype(f32)).astype(f32)
            res[(divname,snapname,'plane32')].update(np.clip(ulpdiff(D,pl),-5,5))
            pl64=(z0+A32.astype(np.float64)*(px-x0)+B32.astype(np.float64)*(py-y0)).astype(f32)
            res[(divname,snapname,'plane32grad-exacteval')].update(np.clip(ulpdiff(D,pl64),-5,5))
            # plane origin at pixel (0,0)
            C=(z0-A*x0-Bc*y0); pc=(C+A*px+Bc*py).astype(f32)
            res[(divname,snapname,'planeC64')].update(np.clip(ulpdiff(D,pc),-5,5))
print('pixels',total,'fragz==depth',fz_eq/total)
for k,v in sorted(res.items(), key=lambda kv:-kv[1][0]):
    print('%-45s exact %.4f  '%(k,v[0]/total), ' '.join('%d:%.4f'%(u,v[u]/total) for u in sorted(v) if u!=0 and v[u]/total>1e-4))
