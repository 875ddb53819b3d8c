import json, numpy as np, collections, sys
import os
# Sponza's triangles in world space (node TRS applied); then exact duplicates among them.
d=os.environ.get('SPONZA', '../shared/corpus/amd/sponza/')
g=json.load(open(d+'Sponza.gltf')); buf=open(d+g['buffers'][0]['uri'],'rb').read()
CT={5126:np.float32,5125:np.uint32,5123:np.uint16,5121:np.uint8}
NC={'SCALAR':1,'VEC2':2,'VEC3':3,'VEC4':4}
def acc(i):
    a=g['accessors'][i]; bv=g['bufferViews'][a['bufferView']]
    off=bv.get('byteOffset',0)+a.get('byteOffset',0); n=NC[a['type']]; dt=CT[a['componentType']]
    stride=bv.get('byteStride',0)
    if stride and stride!=n*np.dtype(dt).itemsize:
        raw=np.frombuffer(buf,np.uint8,count=stride*a['count'],offset=off).reshape(a['count'],stride)
        return raw[:,:n*np.dtype(dt).itemsize].copy().view(dt).reshape(a['count'],n)
    return np.frombuffer(buf,dt,count=a['count']*n,offset=off).reshape(a['count'],n)
tris=[]; info=[]
for ni,node in enumerate(g['nodes']):
    if 'mesh' not in node: continue
    assert 'matrix' not in node and 'children' not in node
    t=np.array(node.get('translation',[0,0,0]),np.float64)
    x,y,z,w=node.get('rotation',[0,0,0,1]); sc=np.array(node.get('scale',[1,1,1]))
    R=np.array([[1-2*(y*y+z*z),2*(x*y-z*w),2*(x*z+y*w)],[2*(x*y+z*w),1-2*(x*x+z*z),2*(y*z-x*w)],[2*(x*z-y*w),2*(y*z+x*w),1-2*(x*x+y*y)]])
    M=R*sc
    for pi,p in enumerate(g['meshes'][node['mesh']]['primitives']):
        pos=acc(p['attributes']['POSITION']).astype(np.float64)@M.T+t
        idx=acc(p['indices']).reshape(-1,3)
        for k,tri in enumerate(idx):
            tris.append(pos[tri]); info.append((ni,pi,k,p.get('material')))
tris=np.array(tris); print('triangles',len(tris))
keys=collections.defaultdict(list)
for i,t in enumerate(tris):
    k=tuple(sorted(tuple(np.round(v,5)) for v in t)); keys[k].append(i)
dups=[v for v in keys.values() if len(v)>1]
print('duplicate vertex sets',len(dups))
orders=collections.Counter()
for v in dups[:100000]:
    a,b=tris[v[0]],tris[v[1]]
    # same order? rotation? reversed?
    def rel(a,b):
        for r in range(3):
            if np.allclose(np.roll(b,r,axis=0),a,atol=1e-6): return 'rot%d'%r
            if np.allclose(np.roll(b[::-1],r,axis=0),a,atol=1e-6): return 'rev%d'%r
        return '?'
    orders[(rel(a,b), info[v[0]][3]==info[v[1]][3])]+=1
print(orders)
for v in dups[:5]: print([info[i] for i in v])
m=g['materials'][3]; print(m.get('name'), m.get('doubleSided'), m.get('alphaMode'))
area=sum(np.linalg.norm(np.cross(tris[v[0]][1]-tris[v[0]][0],tris[v[0]][2]-tris[v[0]][0]))/2 for v in dups)
print('dup area',area, 'mesh', g['nodes'][3].get('name'))
print('double sided mats',[ (i,m.get('name'),m.get('alphaMode')) for i,m in enumerate(g['materials']) if m.get('doubleSided')])
