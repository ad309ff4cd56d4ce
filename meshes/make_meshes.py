#!/usr/bin/env python3
"""Writes and checks the bundled closed quad control meshes (Wavefront OBJ).

    python3 meshes/make_meshes.py           # (re)write every .obj next to this script, then check them
    python3 meshes/make_meshes.py --check   # only check the .obj files already there

Python 3 standard library only. Output is deterministic: vertices are written
with 6 decimals, faces as 1-based `f a b c d`, counter-clockwise seen from
outside (outward normals by the right-hand rule).

The checker reads the written files back and verifies, for each mesh: quads
only, indices in range, no repeated vertex in a face, no duplicate vertex
positions, every directed edge used once and its reverse used once (closed,
edge-manifold, consistently oriented), a single fan around every vertex
(vertex-manifold), one connected component, convex non-degenerate faces,
positive signed volume (outward orientation), the expected genus (Euler
characteristic), and sum over vertices of (4 - valence) = 4 * chi. It prints
face and vertex counts, the valence histogram and how many faces hold two or
more extraordinary (valence != 4) vertices. Exit status 1 on any failure.
"""
import math
import os
import sys
from collections import Counter, defaultdict

HERE = os.path.dirname(os.path.abspath(__file__))


# --------------------------------------------------------------------------
# Small vector helpers


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(dot(a, a))


# --------------------------------------------------------------------------
# Mesh builders. Each returns (positions, faces) with 0-based indices.


def make_cube():
    """Unit cube centred at the origin: 8 vertices of valence 3, 6 quads."""
    h = 0.5
    pos = [(x, y, z) for x in (-h, h) for y in (-h, h) for z in (-h, h)]
    idx = {p: i for i, p in enumerate(pos)}

    def v(x, y, z):
        return idx[(x * h, y * h, z * h)]

    faces = [
        [v(-1, -1, -1), v(-1, 1, -1), v(1, 1, -1), v(1, -1, -1)],  # z = -1/2, normal -z
        [v(-1, -1, 1), v(1, -1, 1), v(1, 1, 1), v(-1, 1, 1)],  # z = +1/2, normal +z
        [v(-1, -1, -1), v(1, -1, -1), v(1, -1, 1), v(-1, -1, 1)],  # y = -1/2, normal -y
        [v(-1, 1, -1), v(-1, 1, 1), v(1, 1, 1), v(1, 1, -1)],  # y = +1/2, normal +y
        [v(-1, -1, -1), v(-1, -1, 1), v(-1, 1, 1), v(-1, 1, -1)],  # x = -1/2, normal -x
        [v(1, -1, -1), v(1, 1, -1), v(1, 1, 1), v(1, -1, 1)],  # x = +1/2, normal +x
    ]
    return pos, faces


def rotate_edge(faces, a, b):
    """Quad-mesh edge rotation of edge {a, b}.

    The quads (a, b, c, d) and (b, a, e, f) sharing the edge form the hexagon
    b c d a e f; they are replaced by (c, d, a, e) and (e, f, b, c), i.e. the
    edge a-b becomes the edge c-e. a and b lose one edge, c and e gain one.
    Returns (c, e)."""
    q1 = q2 = None
    for fi, f in enumerate(faces):
        for k in range(4):
            if f[k] == a and f[(k + 1) % 4] == b:
                q1 = (fi, f[k:] + f[:k])  # (a, b, c, d)
            if f[k] == b and f[(k + 1) % 4] == a:
                q2 = (fi, f[k:] + f[:k])  # (b, a, e, f)
    assert q1 and q2, "edge not found"
    (i1, (_, _, c, d)), (i2, (_, _, e, f)) = q1, q2
    faces[i1] = [c, d, a, e]
    faces[i2] = [e, f, b, c]
    return c, e


def make_torus(nu=12, nv=8, major=2.0, minor=0.7, rotations=((1, 0), (7, 4)), shift=0.3):
    """nu x nv quad grid on a torus, then one edge rotation for each (i, j) in
    `rotations`: the edge from grid vertex (i, j) to (i + 1, j) (along the
    major circle). Its endpoints become valence 3; (i + 1, j + 1) and (i, j - 1)
    become valence 5. The two endpoints are moved `shift` grid steps apart
    along the major direction, so that the two new quads stay convex."""
    def vid(i, j):
        return (i % nu) * nv + (j % nv)

    # Parameter (in grid steps) of each vertex; edge rotations move some.
    param = {vid(i, j): [float(i), float(j)] for i in range(nu) for j in range(nv)}
    faces = [[vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1)] for i in range(nu) for j in range(nv)]
    for (i, j) in rotations:
        a, b = vid(i, j), vid(i + 1, j)
        rotate_edge(faces, a, b)
        param[a][0] -= shift
        param[b][0] += shift
    pos = []
    for k in range(nu * nv):
        u = 2 * math.pi * param[k][0] / nu
        w = 2 * math.pi * param[k][1] / nv
        rr = major + minor * math.cos(w)
        pos.append((rr * math.cos(u), rr * math.sin(u), minor * math.sin(w)))
    return pos, faces


class Revolver:
    """Builds a closed surface of revolution about the z axis from rings of
    vertices (counter-clockwise seen from +z), with quads between rings of
    equal or changing vertex counts and all-quad poles."""

    def __init__(self):
        self.pos = []
        self.faces = []

    def point(self, r, z, angle):
        self.pos.append((r * math.cos(angle), r * math.sin(angle), z))
        return len(self.pos) - 1

    def ring(self, n, r, z, r_odd=None, z_odd=None):
        """n vertices at angles 2 pi k / n; odd k at (r_odd, z_odd) if given."""
        out = []
        for k in range(n):
            odd = k % 2 == 1 and r_odd is not None
            out.append(self.point(r_odd if odd else r, z_odd if odd else z, 2 * math.pi * k / n))
        return out

    def pole(self, z):
        return self.point(0.0, z, 0.0)

    def cap(self, pole, ring, top):
        """Pole of valence len(ring) / 2: quads (pole, ring[2i], ring[2i+1], ring[2i+2])."""
        n = len(ring)
        assert n % 2 == 0
        for i in range(n // 2):
            a, b, c = ring[2 * i], ring[2 * i + 1], ring[(2 * i + 2) % n]
            self.faces.append([pole, a, b, c] if top else [pole, c, b, a])

    def band(self, lo, hi):
        """Regular quads between two rings of equal size (lo below hi)."""
        n = len(lo)
        assert len(hi) == n
        for k in range(n):
            self.faces.append([lo[k], lo[(k + 1) % n], hi[(k + 1) % n], hi[k]])

    def nudge(self, v, dz):
        x, y, z = self.pos[v]
        self.pos[v] = (x, y, z + dz)

    def halve(self, lo, hi, dz=0.0):
        """Rings of 4m (lo) and 2m (hi) vertices. Per quarter turn (4 lo edges,
        2 hi edges): regular quad, a quad with 2 lo edges, regular quad. The hi
        vertex above the middle lo vertex gets valence 5, that lo vertex 3,
        and is lowered by dz so that the quad with 2 lo edges stays convex."""
        m = len(hi) // 2
        assert len(lo) == 4 * m
        L = lambda k: lo[k % len(lo)]
        H = lambda k: hi[k % len(hi)]
        for q in range(m):
            b0, b1, b2, b3, b4 = (L(4 * q + s) for s in range(5))
            t0, t1, t2 = (H(2 * q + s) for s in range(3))
            self.faces += [[b0, b1, t1, t0], [b1, b2, b3, t1], [b3, b4, t2, t1]]
            self.nudge(b2, -dz)

    def widen(self, lo, hi, dz=0.0):
        """Rings of 4m (lo) and 6m (hi) vertices. Per step (4 lo edges, 6 hi
        edges): regular, regular, a quad with 2 hi edges, regular, regular. The
        lo vertex below the middle hi vertex gets valence 5, that hi vertex 3,
        and is raised by dz so that the quad with 2 hi edges stays convex."""
        m = len(lo) // 4
        assert len(hi) == 6 * m
        L = lambda k: lo[k % len(lo)]
        H = lambda k: hi[k % len(hi)]
        for q in range(m):
            b0, b1, b2, b3, b4 = (L(4 * q + s) for s in range(5))
            t0, t1, t2, t3, t4, t5, t6 = (H(6 * q + s) for s in range(7))
            self.faces += [[b0, b1, t1, t0], [b1, b2, t2, t1], [b2, t4, t3, t2], [b2, b3, t5, t4], [b3, b4, t6, t5]]
            self.nudge(t3, dz)


def make_chess_piece():
    """Pawn-like surface of revolution, z up, height about 2.5.

    Flat base closed by a pole of valence 8 (16-vertex ring, 8 valence-3
    vertices); base band of 16 segments; 16 -> 8 reduction above the base
    (4 valence-3, 4 valence-5 vertices); waist, neck and collar with 8
    segments; 8 -> 12 widening into the head (2 valence-5, 2 valence-3
    vertices); spherical head with 12 segments closed by a pole of valence 6
    (12-vertex ring, 6 valence-3 vertices)."""
    R = Revolver()
    bottom = R.pole(0.0)
    rings16 = [R.ring(16, 0.50, 0.0, r_odd=0.78, z_odd=0.0)]  # flat bottom, around the pole
    for r, z in [(0.98, 0.0), (1.04, 0.10), (0.98, 0.20), (0.82, 0.30), (0.66, 0.40)]:  # base rim and top
        rings16.append(R.ring(16, r, z))
    rings8 = [R.ring(8, r, z) for r, z in [
        (0.52, 0.55),  # foot of the waist
        (0.42, 0.80), (0.35, 1.10), (0.31, 1.35),  # waist up to the neck
        (0.52, 1.45), (0.54, 1.53), (0.33, 1.62),  # collar
    ]]
    # Head: sphere of radius 0.46 centred at z = 2.08; rings by polar angle from the top.
    c, rad = 2.08, 0.46
    sph = lambda deg: (rad * math.sin(math.radians(deg)), c + rad * math.cos(math.radians(deg)))
    rings12 = [R.ring(12, *sph(d)) for d in (145, 120, 95, 70, 47)]
    (re, ze), (ro, zo) = sph(20), sph(30)
    rings12.append(R.ring(12, re, ze, r_odd=ro, z_odd=zo))  # around the top pole
    top = R.pole(c + rad)

    R.cap(bottom, rings16[0], top=False)
    for lo, hi in zip(rings16, rings16[1:]):
        R.band(lo, hi)
    R.halve(rings16[-1], rings8[0], dz=0.04)
    for lo, hi in zip(rings8, rings8[1:]):
        R.band(lo, hi)
    R.widen(rings8[-1], rings12[0], dz=0.06)
    for lo, hi in zip(rings12, rings12[1:]):
        R.band(lo, hi)
    R.cap(top, rings12[-1], top=True)
    return R.pos, R.faces


def make_rook():
    """Rook-like surface of revolution, z up, height about 2.3: flat base
    closed by a pole of valence 8 (16-vertex ring, 8 valence-3 vertices);
    base band of 16 segments; 16 -> 24 widening into the tower (4 valence-5,
    4 valence-3 vertices); a tower of 24 segments flaring into a crown whose
    rim alternates high and low (12 merlons), down its inside to a recessed
    platform; 24 -> 12 reduction (6 valence-3, 6 valence-5 vertices) and a
    pole of valence 6 (12-vertex ring, 6 valence-3 vertices) at its centre."""
    R = Revolver()
    bottom = R.pole(0.0)
    rings16 = [R.ring(16, 0.50, 0.0, r_odd=0.74, z_odd=0.0)]
    for r, z in [(0.96, 0.0), (1.02, 0.10), (0.96, 0.22), (0.82, 0.32)]:
        rings16.append(R.ring(16, r, z))
    rings24 = [R.ring(24, r, z) for r, z in [
        (0.70, 0.44), (0.64, 0.65), (0.60, 0.95), (0.58, 1.25), (0.60, 1.50),  # tower
        (0.68, 1.68), (0.78, 1.80), (0.81, 1.92),  # flare
    ]]
    rings24.append(R.ring(24, 0.82, 2.28, r_odd=0.82, z_odd=2.06))  # outer rim: merlons and gaps
    rings24.append(R.ring(24, 0.66, 2.30, r_odd=0.66, z_odd=2.08))  # inner rim
    rings24.append(R.ring(24, 0.60, 2.00))  # inside wall, down to the platform
    rings12 = [R.ring(12, 0.42, 1.95), R.ring(12, 0.16, 1.93, r_odd=0.26, z_odd=1.93)]
    top = R.pole(1.93)

    R.cap(bottom, rings16[0], top=False)
    for lo, hi in zip(rings16, rings16[1:]):
        R.band(lo, hi)
    R.widen(rings16[-1], rings24[0], dz=0.04)
    for lo, hi in zip(rings24, rings24[1:]):
        R.band(lo, hi)
    R.halve(rings24[-1], rings12[0], dz=-0.02)
    R.band(rings12[0], rings12[1])
    R.cap(top, rings12[-1], top=True)
    return R.pos, R.faces


def make_bumpy_sphere(m=4, amplitude=0.15):
    """Cube subdivided m x m per side, projected to the sphere (equal-angle
    warp) and displaced radially by a smooth bump function: valence 3 at the 8
    cube corners, 4 elsewhere; no face holds two extraordinary vertices."""
    ids = {}
    pos = []

    def vert(p):  # p: integer point on the surface of the cube [0, m]^3
        if p not in ids:
            q = [math.tan(math.pi / 4 * (2.0 * t / m - 1.0)) for t in p]
            s = norm(q)
            d = (q[0] / s, q[1] / s, q[2] / s)
            r = 1.0 + amplitude * math.sin(3 * d[0] + 1) * math.sin(3 * d[1] + 2) * math.sin(3 * d[2] + 3)
            ids[p] = len(pos)
            pos.append((r * d[0], r * d[1], r * d[2]))
        return ids[p]

    faces = []
    for axis in range(3):
        for side in (0, m):
            u_ax, v_ax = (axis + 1) % 3, (axis + 2) % 3  # e_u x e_v = e_axis
            if side == 0:  # outward normal is -e_axis
                u_ax, v_ax = v_ax, u_ax
            for i in range(m):
                for j in range(m):
                    quad = []
                    for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1)):
                        p = [0, 0, 0]
                        p[axis] = side
                        p[u_ax] = i + di
                        p[v_ax] = j + dj
                        quad.append(vert(tuple(p)))
                    faces.append(quad)
    return pos, faces


MESHES = [
    # file name, builder, expected genus, description
    ("cube.obj", make_cube, 0, "unit cube centred at the origin"),
    ("torus-3-5.obj", make_torus, 1, "12 x 8 torus (R = 2, r = 0.7) with 2 edge rotations"),
    ("chess-piece.obj", make_chess_piece, 0, "pawn-like surface of revolution with poles of valence 8 and 6"),
    ("bumpy-sphere.obj", make_bumpy_sphere, 0, "cube-sphere (4 x 4 quads per side) with radial bumps"),
    ("rook.obj", make_rook, 0, "rook-like surface of revolution with a crown of 12 merlons"),
    ("quad-sphere.obj", lambda: make_bumpy_sphere(m=3, amplitude=0.0), 0,
     "cube-sphere (3 x 3 quads per side), a starting control mesh for stencilfit"),
]


# --------------------------------------------------------------------------
# OBJ I/O


def fmt(x):
    return "%.6f" % (round(x, 6) + 0.0)  # + 0.0 turns -0.0 into 0.0


def write_obj(path, pos, faces, comment):
    lines = ["# %s" % comment, "# generated by meshes/make_meshes.py; %d vertices, %d quads" % (len(pos), len(faces))]
    lines += ["v %s %s %s" % tuple(fmt(c) for c in p) for p in pos]
    lines += ["f %s" % " ".join(str(i + 1) for i in f) for f in faces]
    with open(path, "w", newline="\n") as out:
        out.write("\n".join(lines) + "\n")


def read_obj(path):
    pos, faces = [], []
    with open(path) as f:
        for line in f:
            t = line.split()
            if not t:
                continue
            if t[0] == "v":
                pos.append(tuple(float(x) for x in t[1:4]))
            elif t[0] == "f":
                faces.append([int(x.split("/")[0]) - 1 for x in t[1:]])
    return pos, faces


# --------------------------------------------------------------------------
# Checker


def check_mesh(name, pos, faces, genus):
    """Validates a closed quad mesh; returns (list of errors, statistics dict)."""
    errors = []
    nv, nf = len(pos), len(faces)
    for fi, f in enumerate(faces):
        if len(f) != 4:
            errors.append("face %d has %d vertices" % (fi, len(f)))
        if any(i < 0 or i >= nv for i in f):
            errors.append("face %d has an index out of range" % fi)
        if len(set(f)) != len(f):
            errors.append("face %d repeats a vertex" % fi)
    if errors:
        return errors, None

    # Duplicate positions.
    seen = {}
    for i, p in enumerate(pos):
        key = tuple(round(c, 5) for c in p)
        if key in seen:
            errors.append("vertices %d and %d coincide" % (seen[key], i))
        seen[key] = i

    # Directed edges: each once, its reverse once.
    directed = Counter()
    for f in faces:
        for k in range(4):
            directed[(f[k], f[(k + 1) % 4])] += 1
    for (a, b), count in directed.items():
        if count != 1:
            errors.append("directed edge %d->%d used %d times" % (a, b, count))
        if directed.get((b, a), 0) != 1:
            errors.append("edge %d->%d has no single opposite %d->%d (boundary or non-manifold)" % (a, b, b, a))
    n_edges = len(directed) // 2

    # Vertex-manifold: the faces around each vertex form one cycle.
    out_to_in = defaultdict(dict)  # vertex -> {next vertex: previous vertex} per incident face
    for f in faces:
        for k in range(4):
            out_to_in[f[k]][f[(k + 1) % 4]] = f[(k + 3) % 4]
    valence = [0] * nv
    for v in range(nv):
        fan = out_to_in.get(v, {})
        valence[v] = len(fan)
        if not fan:
            errors.append("vertex %d is unused" % v)
            continue
        start = next(iter(fan))
        w, steps = start, 0
        while True:
            # Face with outgoing edge v->w has incoming edge p->v; the next face
            # around v has outgoing edge v->p.
            w = fan[w]
            steps += 1
            if w not in fan or w == start or steps > len(fan):
                break
        if w != start or steps != len(fan):
            errors.append("vertex %d: its faces do not form a single fan" % v)

    # Connectivity.
    adj = defaultdict(set)
    for (a, b) in directed:
        adj[a].add(b)
    comp, stack = {0}, [0]
    while stack:
        for w in adj[stack.pop()]:
            if w not in comp:
                comp.add(w)
                stack.append(w)
    if len(comp) != nv:
        errors.append("mesh has more than one connected component")

    # Face shape: convex, non-degenerate (corner normals agree with the face's Newell normal).
    worst_corner = float("inf")
    for fi, f in enumerate(faces):
        P = [pos[i] for i in f]
        newell = (0.0, 0.0, 0.0)
        for k in range(4):
            newell = add(newell, cross(P[k], P[(k + 1) % 4]))
        n_len = norm(newell)
        if n_len < 1e-12:
            errors.append("face %d has zero area" % fi)
            continue
        nrm = tuple(c / n_len for c in newell)
        for k in range(4):
            e0, e1 = sub(P[k], P[k - 1]), sub(P[(k + 1) % 4], P[k])
            s = dot(cross(e0, e1), nrm) / (norm(e0) * norm(e1))  # sine of the turning angle
            worst_corner = min(worst_corner, s)
            if s <= 1e-3:
                errors.append("face %d is not convex or degenerate at corner %d (sin = %.3g)" % (fi, k, s))

    # Signed volume by the divergence theorem (each quad as a fan of 2 triangles).
    vol = 0.0
    for f in faces:
        a = pos[f[0]]
        for k in (1, 2):
            vol += dot(a, cross(pos[f[k]], pos[f[k + 1]])) / 6.0
    if vol <= 0:
        errors.append("signed volume %.6g <= 0: faces are oriented inwards" % vol)

    chi = nv - n_edges + nf
    if chi != 2 - 2 * genus:
        errors.append("Euler characteristic %d, expected %d (genus %d)" % (chi, 2 - 2 * genus, genus))
    if sum(4 - d for d in valence) != 4 * chi:
        errors.append("sum of (4 - valence) is %d, expected 4 chi = %d" % (sum(4 - d for d in valence), 4 * chi))

    ev_per_face = Counter(sum(valence[i] != 4 for i in f) for f in faces)
    stats = {
        "faces": nf,
        "vertices": nv,
        "edges": n_edges,
        "chi": chi,
        "genus": (2 - chi) // 2,
        "volume": vol,
        "valences": dict(sorted(Counter(valence).items())),
        "ev_per_face": dict(sorted(ev_per_face.items())),
        "faces_with_2plus_ev": sum(c for k, c in ev_per_face.items() if k >= 2),
        "min_corner_sine": worst_corner,
    }
    return errors, stats


def check_all():
    ok = True
    for fname, _, genus, _ in MESHES:
        path = os.path.join(HERE, fname)
        if not os.path.exists(path):
            print("%-17s MISSING" % fname)
            ok = False
            continue
        pos, faces = read_obj(path)
        errors, s = check_mesh(fname, pos, faces, genus)
        if errors:
            ok = False
            print("%-17s FAIL" % fname)
            for e in errors[:20]:
                print("    " + e)
            continue
        hist = ", ".join("%d: %d" % kv for kv in s["valences"].items())
        evf = ", ".join("%d: %d" % kv for kv in s["ev_per_face"].items())
        print("%-17s OK  faces %3d  vertices %3d  edges %3d  genus %d  volume %.4f" % (
            fname, s["faces"], s["vertices"], s["edges"], s["genus"], s["volume"]))
        print("%-17s     valences {%s}" % ("", hist))
        print("%-17s     faces by number of extraordinary vertices {%s}; faces with >= 2: %d%s" % (
            "", evf, s["faces_with_2plus_ev"],
            " (refined once by the runtime)" if s["faces_with_2plus_ev"] else ""))
        print("%-17s     smallest corner sine %.3f (convex, non-degenerate)" % ("", s["min_corner_sine"]))
    return ok


def main(argv):
    if "--check" not in argv:
        for fname, build, _, comment in MESHES:
            pos, faces = build()
            write_obj(os.path.join(HERE, fname), pos, faces, comment)
    ok = check_all()
    print("all checks passed" if ok else "CHECKS FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
