# Generates an off-centre, non-symmetric triangle mesh (icosphere level 1, warped, translated).
import math, sys
t = (1 + 5 ** 0.5) / 2
V = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
     (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
V = [tuple(c / math.sqrt(sum(a * a for a in v)) for c in v) for v in V]
F = [(0,11,5),(0,5,1),(0,1,7),(0,7,10),(0,10,11),(1,5,9),(5,11,4),(11,10,2),(10,7,6),(7,1,8),
     (3,9,4),(3,4,2),(3,2,6),(3,6,8),(3,8,9),(4,9,5),(2,4,11),(6,2,10),(8,6,7),(9,8,1)]
mid = {}
def m(a, b):
    k = (min(a, b), max(a, b))
    if k not in mid:
        p = [(V[a][i] + V[b][i]) / 2 for i in range(3)]
        n = math.sqrt(sum(c * c for c in p))
        V.append(tuple(c / n for c in p)); mid[k] = len(V) - 1
    return mid[k]
F2 = []
for a, b, c in F:
    ab, bc, ca = m(a, b), m(b, c), m(c, a)
    F2 += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
out = []
for x, y, z in V:
    X, Y, Z = 2 * x, y, 0.5 * z          # stretch
    if x > 0: X *= 1.6                    # asymmetric: +x half longer
    if y > 0: Z += 0.25 * y               # asymmetric tilt of the +y half
    out.append((X + 3, Y - 1, Z + 2))     # translate
with open(sys.argv[1], "w") as f:
    f.write("# offcentre: icosphere(1) scaled (2,1,0.5), +x half *1.6, z += 0.25*y for y>0, translated (3,-1,2)\n")
    for p in out: f.write("v %.17g %.17g %.17g\n" % p)
    for a, b, c in F2: f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))
