# A closed, jittered UV sphere as OFF on stdout: many slivers near the poles and the silhouette.
#   python3 jittered_sphere.py SEED LATITUDES LONGITUDES
# sliver-sphere.off is `python3 jittered_sphere.py 3 10 20`: at 20x20 pixels, snapping to the fixed4 grid
# turns two of its projected triangles over (rast check once counted them for the wrong side).
import math, random, sys
seed, n_lat, n_lon = int(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3])
random.seed(seed)
verts = [(0, 0, 1)]
for i in range(1, n_lat):
    th = math.pi * i / n_lat
    for j in range(n_lon):
        ph = 2 * math.pi * j / n_lon + random.uniform(-0.3, 0.3) / n_lon
        r = 1 + random.uniform(-0.05, 0.05)
        verts.append((r * math.sin(th) * math.cos(ph), r * math.sin(th) * math.sin(ph), r * math.cos(th)))
verts.append((0, 0, -1))
faces = []
def idx(i, j): return 1 + (i - 1) * n_lon + (j % n_lon)
for j in range(n_lon): faces.append((0, idx(1, j), idx(1, j + 1)))
for i in range(1, n_lat - 1):
    for j in range(n_lon):
        a, b, c, d = idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)
        faces.append((a, b, c)); faces.append((a, c, d))
last = len(verts) - 1
for j in range(n_lon): faces.append((last, idx(n_lat - 1, j + 1), idx(n_lat - 1, j)))
print("OFF"); print(len(verts), len(faces), 0)
for v in verts: print("%.17g %.17g %.17g" % v)
for f in faces: print(3, *f)
