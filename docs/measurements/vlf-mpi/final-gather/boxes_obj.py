# SPDX-License-Identifier: BSD-3-Clause
# Writes the 900 boxes of `mesolight bench vlf-accuracy` (application/VlfAccuracyScenes.cxx,
# Boxes()) as OBJ + MTL, for timing `vlf propagate` on them: python3 boxes_obj.py boxes.obj
import math, sys
out = sys.argv[1]
def hsh(i, j, k):
    M = 0xffffffff
    h = ((i * 73856093) & M) ^ ((j * 19349663) & M) ^ ((k * 83492791) & M)
    h ^= h >> 13; h = (h * 0x5bd1e995) & M; h ^= h >> 15
    return (h & 0xffffff) / 16777216.0
V = []; F = []
def sub(a, b): return [a[i] - b[i] for i in range(3)]
def add(a, b): return [a[i] + b[i] for i in range(3)]
def mul(s, a): return [s * x for x in a]
def cross(a, b): return [a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0]]
def dot(a, b): return sum(a[i]*b[i] for i in range(3))
def quad(a, b, c, d, front, mat):
    if dot(cross(sub(b, a), sub(c, a)), front) < 0: b, d = d, b
    base = len(V) + 1
    V.extend([a, b, c, d]); F.append((mat, [base, base+1, base+2, base+3]))
def axisbox(lo, up, mat, deg):
    r = math.radians(deg); size = sub(up, lo)
    ex = [math.cos(r), 0, -math.sin(r)]; ez = [math.sin(r), 0, math.cos(r)]
    c = mul(0.5, add(lo, up))
    o = sub(sub([c[0], lo[1], c[2]], mul(0.5*size[0], ex)), mul(0.5*size[2], ez))
    E = [mul(size[0], ex), mul(size[2], ez), [0, size[1], 0]]
    centre = add(o, mul(0.5, add(add(E[0], E[1]), E[2])))
    for axis in range(3):
        u = E[(axis+1) % 3]; v = E[(axis+2) % 3]
        for side in range(2):
            if axis == 2 and side == 0: continue
            p = add(o, mul(side, E[axis]))
            outv = sub(add(p, mul(0.5, add(u, v))), centre)
            quad(p, add(p, u), add(add(p, u), v), add(p, v), outv, mat)
quad([-5,0,-5],[5,0,-5],[5,0,5],[-5,0,5],[0,1,0],"floor")
cols = ["white", "orange", "blue"]
for i in range(30):
    for j in range(30):
        side = 0.08 + 0.12*hsh(i,j,1); height = 0.04 + 0.3*hsh(i,j,2)
        x = -4.35 + 0.3*i; z = -4.35 + 0.3*j
        axisbox([x-0.5*side, 0, z-0.5*side], [x+0.5*side, height, z+0.5*side], cols[(i+2*j)%3], 90*hsh(i,j,3))
quad([-1,3.5,-1],[1,3.5,-1],[1,3.5,1],[-1,3.5,1],[0,-1,0],"lamp")
mtl = out[:-4] + ".mtl"
with open(mtl, "w") as m:
    for n, kd, ke in [("floor",(0.6,)*3,(0,0,0)),("white",(0.8,)*3,(0,0,0)),("orange",(0.7,0.4,0.15),(0,0,0)),("blue",(0.2,0.3,0.65),(0,0,0)),("lamp",(0.8,)*3,(8,8,8))]:
        m.write("newmtl %s\nKd %g %g %g\nKe %g %g %g\n" % ((n,)+kd+ke))
with open(out, "w") as f:
    f.write("mtllib %s\n" % mtl.split("/")[-1])
    for v in V: f.write("v %.7g %.7g %.7g\n" % tuple(v))
    cur = None
    for mat, idx in F:
        if mat != cur: f.write("usemtl %s\n" % mat); cur = mat
        f.write("f %d %d %d %d\n" % tuple(idx))
print(len(V), "vertices", len(F), "quads")
