# Exact UV oracle for a frame exported with `trisect export` and rendered by Trisect and by glref:
# for every pixel both drew with the same triangle, the ray through the pixel centre is intersected
# with that triangle in float64, and both UV outputs are compared with the texel coordinates there.
# Usage: exact-uv-oracle.py scene.obj tex.ppm ours.pfm gl.pfm W H ex ey ez tx ty tz fovY  (needs numpy)
import sys, numpy as np
obj, tex, ours, gl = sys.argv[1:5]
W, H = int(sys.argv[5]), int(sys.argv[6])
eye = np.array(list(map(float, sys.argv[7:10]))); tgt = np.array(list(map(float, sys.argv[10:13]))); fov = float(sys.argv[13])
V=[]; T=[]; F=[]
for line in open(obj):
    p=line.split()
    if not p: continue
    if p[0]=='v': V.append(list(map(float,p[1:4])))
    elif p[0]=='vt': T.append(list(map(float,p[1:3])))
    elif p[0]=='f':
        c=[x.split('/') for x in p[1:]]
        for k in range(1,len(c)-1):
            F.append([(int(c[i][0])-1, int(c[i][1])-1) for i in (0,k,k+1)])
V=np.array(V,np.float32).astype(np.float64); T=np.array(T,np.float32).astype(np.float64)
hdr=open(tex,'rb').read(20).split(); tw,th=int(hdr[1]),int(hdr[2])
def pfm(p):
    b=open(p,'rb').read(); pos=0; nl=0
    while nl<3:
        if b[pos]==10: nl+=1
        pos+=1
    a=np.frombuffer(b[pos:],dtype='<f4').reshape(H,W,3)[::-1]  # rows top first
    return a
o=pfm(ours); g=pfm(gl)
same=(o[:,:,2]!=0)&(o[:,:,2]==g[:,:,2])
ys,xs=np.nonzero(same)
ids=o[ys,xs,2].astype(np.int64)-1
f=(tgt-eye)/np.linalg.norm(tgt-eye); r=np.cross(f,[0,1,0]); r/=np.linalg.norm(r); u=np.cross(r,f)
th_=np.tan(np.radians(fov)/2); asp=W/H
nx=(xs+0.5)/W*2-1; ny=1-(ys+0.5)/H*2
d=f[None,:]+r[None,:]*(nx*th_*asp)[:,None]+u[None,:]*(ny*th_)[:,None]
Fa=np.array(F)
P=V[Fa[ids][:,:,0]]; UV=T[Fa[ids][:,:,1]]*np.array([tw,th])
e1=P[:,1]-P[:,0]; e2=P[:,2]-P[:,0]
pv=np.cross(d,e2); det=np.einsum('ij,ij->i',e1,pv)
tv=eye[None,:]-P[:,0]; b1=np.einsum('ij,ij->i',tv,pv)/det
qv=np.cross(tv,e1); b2=np.einsum('ij,ij->i',d,qv)/det; b0=1-b1-b2
ex=b0[:,None]*UV[:,0]+b1[:,None]*UV[:,1]+b2[:,None]*UV[:,2]
eo=np.hypot(o[ys,xs,0]-ex[:,0], o[ys,xs,1]-ex[:,1]); eg=np.hypot(g[ys,xs,0]-ex[:,0], g[ys,xs,1]-ex[:,1])
mag=np.abs(ex).max(axis=1)
print(f"pixels {len(eo)}: Trisect vs exact max {eo.max():.5f} (>{0.02}: {(eo>0.02).sum()}), OpenGL vs exact max {eg.max():.5f} (>{0.02}: {(eg>0.02).sum()}); worst OpenGL pixel at texel magnitude {mag[eg.argmax()]:.0f}")
small=mag<2048
dd=np.hypot(o[ys,xs,0]-g[ys,xs,0], o[ys,xs,1]-g[ys,xs,1])
print(f"Trisect vs OpenGL where texel coordinates < 2048: max {dd[small].max():.5f} over {small.sum()} px; elsewhere max {dd[~small].max() if (~small).any() else 0:.5f}")
