import numpy as np, sys, collections
d=sys.argv[1]; W,H=640,360
f32=np.float32
def ulpdiff(a,b):
    ai=a.view(np.int32).astype(np.int64); bi=b.view(np.int32).astype(np.int64); return bi-ai
res=collections.defaultdict(lambda: collections.Counter()); total=0
fz_eq=0
for b in range(8):
    clip=np.fromfile(f'{d}/b{b}.clip',np.float32).reshape(-1,3,4)
    ids=np.fromfile(f'{d}/b{b}.ids',np.uint32).reshape(H,W)
    D=np.fromfile(f'{d}/b{b}.depth',np.float32).reshape(H,W)
    FZ=np.fromfile(f'{d}/b{b}.fragz',np.uint32).reshape(H,W).view(np.float32)
    yy,xx=np.nonzero(ids); t=ids[yy,xx].astype(np.int64)-1
    D=D[yy,xx]; FZ=FZ[yy,xx]; total+=len(t); fz_eq+=(FZ.view(np.uint32)==D.view(np.uint32)).sum()
    c=clip[t]  # n,3,4
    px=(xx+0.5).astype(np.float64); py=(yy+0.5).astype(np.float64)
    half=np.array([W/2,H/2],np.float32)
    for divname in ('div','rcp'):
        if divname=='div': ndc=(c[:,:,:3]/c[:,:,3:4]).astype(f32)
        else: ndc=(c[:,:,:3]*(f32(1)/c[:,:,3:4]).astype(f32)).astype(f32)
        win=(ndc[:,:,:2]*half).astype(f32)+half   # two roundings
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
