# Triangles of Sponza within `delta` of another's plane, facing within 2.6 degrees, overlapping
# it in projection: where a depth tie between two surfaces can happen at Sponza's far side.
import os
exec(open(os.path.join(os.path.dirname(os.path.abspath(__file__)), 'gltf_triangles.py')).read().split("tris=np.array(tris)")[0])
import sys
tris=np.array(tris); info=np.array(info)
delta=float(sys.argv[1])
n=np.cross(tris[:,1]-tris[:,0],tris[:,2]-tris[:,0]); area=np.linalg.norm(n,axis=1)/2
ok=area>1e-12; nn=n/np.maximum(np.linalg.norm(n,axis=1),1e-30)[:,None]
lo=tris.min(1)-delta; hi=tris.max(1)+delta
# uniform grid hashing of boxes
cell=0.5
from collections import defaultdict
grid=defaultdict(list)
for i in np.nonzero(ok)[0]:
    a=np.floor(lo[i]/cell).astype(int); b=np.floor(hi[i]/cell).astype(int)
    if np.prod(b-a+1)>2000: continue
    for x in range(a[0],b[0]+1):
        for y in range(a[1],b[1]+1):
            for z in range(a[2],b[2]+1): grid[(x,y,z)].append(i)
seen=set(); flagged=set()
def tri2d(t,ax): return t[:,[a for a in range(3) if a!=ax]]
def overlap(P,Q):
    for A_,B_ in ((P,Q),(Q,P)):
        for k in range(3):
            e=A_[(k+1)%3]-A_[k]; nrm=np.array([-e[1],e[0]])
            pa=A_@nrm; pb=B_@nrm; s=1e-9*np.abs(pa).max()
            if pa.max()<=pb.min()+s or pb.max()<=pa.min()+s: return False
    return True
for cellv in grid.values():
    if len(cellv)<2: continue
    for ii in range(len(cellv)):
        a=cellv[ii]
        for b in cellv[ii+1:]:
            if (a,b) in seen: continue
            seen.add((a,b))
            if abs(nn[a]@nn[b])<0.999: continue
            if (lo[a]>hi[b]).any() or (lo[b]>hi[a]).any(): continue
            da=np.abs((tris[b]-tris[a][0])@nn[a]); db=np.abs((tris[a]-tris[b][0])@nn[b])
            if da.max()>delta and db.max()>delta: continue
            ax=np.argmax(np.abs(nn[a]))
            if overlap(tri2d(tris[a],ax),tri2d(tris[b],ax)):
                flagged.add(a); flagged.add(b)
fl=sorted(flagged)
print('delta',delta,'flagged',len(fl),'area %.1f of %.1f'%(area[fl].sum(),area.sum()))
import collections
print(collections.Counter(g['nodes'][info[i][0]].get('name').split('.')[0] for i in fl).most_common(12))
