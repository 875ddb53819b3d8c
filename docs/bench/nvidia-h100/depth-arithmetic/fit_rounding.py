import numpy as np, sys, collections
d=sys.argv[1]; W,H=640,360
f32=np.float32
def ulpdiff(a,b):
    return b.view(np.int32).astype(np.int64)-a.view(np.int32).astype(np.int64)
def round_dir(x, mode):
    r=x.astype(f32)
    if mode=='near': return r
    r64=r.astype(np.float64)
    if mode=='up':
        m=r64<x; r[m]=np.nextafter(r[m],f32(np.inf)); return r
    if mode=='down':
        m=r64>x; r[m]=np.nextafter(r[m],f32(-np.inf)); return r
res=collections.defaultdict(collections.Counter); total=0
for b in range(8):
    clip=np.fromfile(f'{d}/b{b}.clip',np.float32).reshape(-1,3,4)
    ids=np.fromfile(f'{d}/b{b}.ids',np.uint32).reshape(H,W)
    D=np.fromfile(f'{d}/b{b}.depth',np.float32).reshape(H,W)
    yy,xx=np.nonzero(ids); t=ids[yy,xx].astype(np.int64)-1; D=D[yy,xx]; total+=len(t)
    c=clip[t]; px=xx+0.5; py=yy+0.5
    half=np.array([W/2,H/2],np.float32)
    ndc=(c[:,:,:3]/c[:,:,3:4]).astype(f32)
    win=(ndc[:,:,:2]*half).astype(f32)+half
    V=np.round(win.astype(np.float64)*256)/256
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
        print('example mismatches (up):', [(int(xx[i]),int(yy[i]),int(t[i]),int(u[i]), float(D[i])) for i in np.nonzero(u)[0][:8]])
print('pixels',total)
for k,v in sorted(res.items(), key=lambda kv:-kv[1][0]):
    print('%-25s exact %.4f  '%(k,v[0]/total), ' '.join('%d:%.4f'%(u,v[u]/total) for u in sorted(v) if u!=0 and v[u]/total>1e-5))
