#!/usr/bin/env python3
"""Writes and checks the bundled closed triangle control meshes (Wavefront OBJ).

    python3 meshes/make_triangle_meshes.py           # (re)write the .obj files, then check them
    python3 meshes/make_triangle_meshes.py --check   # only check the files already there

Python 3 standard library only; deterministic output (6 decimals, 1-based
`f a b c`, counter-clockwise seen from outside). The checker reads each file
back and verifies: triangles only, indices in range, no repeated vertex in a
face, every directed edge used once and its reverse once (closed, oriented),
a single fan round every vertex, positive signed volume, the expected genus,
and sum over vertices of (6 - valence) = 6 * chi. It prints the valence
histogram and how many faces hold two or more extraordinary (valence != 6)
vertices. Exit status 1 on any failure.
"""
import math
import os
import sys
from collections import Counter, defaultdict

HERE = os.path.dirname(os.path.abspath(__file__))


def make_icosahedron():
    t = (1 + 5 ** 0.5) / 2
    pos = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
           (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    s = 1 / math.sqrt(1 + t * t)
    pos = [(x * s, y * s, z * s) for x, y, z in pos]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
             (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    return pos, faces, 0


def flip(faces, a, b):
    """Replaces the two triangles on edge (a, b) by the other diagonal of their quad."""
    f1 = next(i for i, f in enumerate(faces) if any((f[k], f[(k + 1) % 3]) == (a, b) for k in range(3)))
    f2 = next(i for i, f in enumerate(faces) if any((f[k], f[(k + 1) % 3]) == (b, a) for k in range(3)))
    c = next(v for v in faces[f1] if v not in (a, b))
    d = next(v for v in faces[f2] if v not in (a, b))
    faces[f1] = (a, d, c)  # a -> b -> c and b -> a -> d become the triangles on edge (c, d)
    faces[f2] = (b, c, d)


def make_torus(nu=12, nv=8, major=2.0, minor=0.7):
    """A triangulated torus; two edge flips make 4 vertices of valence 5 and 4 of valence 7."""
    pos = []
    for i in range(nu):
        for j in range(nv):
            u, v = 2 * math.pi * i / nu, 2 * math.pi * j / nv
            r = major + minor * math.cos(v)
            pos.append((r * math.cos(u), r * math.sin(u), minor * math.sin(v)))
    vid = lambda i, j: (i % nu) * nv + (j % nv)
    faces = []
    for i in range(nu):
        for j in range(nv):
            a, b, c, d = vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1)
            faces += [(a, b, c), (a, c, d)]
    flip(faces, vid(2, 1), vid(3, 2))
    flip(faces, vid(8, 5), vid(9, 6))
    return pos, faces, 1


def make_mix():
    """A heptagonal bipyramid (poles of valence 7, equator of valence 4) with
    two faces capped by low pyramids (valence 3 at the caps; the capped
    faces' corners rise to 5 on the equator and 8 at the poles)."""
    m = 7
    pos = [(math.cos(2 * math.pi * k / m), math.sin(2 * math.pi * k / m), 0.0) for k in range(m)]
    pos += [(0, 0, 1.2), (0, 0, -1.2)]
    top, bottom = m, m + 1
    faces = []
    for k in range(m):
        faces.append((k, (k + 1) % m, top))
        faces.append(((k + 1) % m, k, bottom))
    for f in (0, 7):  # one upper and one lower face
        a, b, c = faces[f]
        centre = tuple(sum(pos[v][i] for v in (a, b, c)) / 3 for i in range(3))
        n = norm(cross(sub(pos[b], pos[a]), sub(pos[c], pos[a])))
        apex = tuple(centre[i] + 0.25 * n[i] for i in range(3))
        pos.append(apex)
        p = len(pos) - 1
        faces[f] = (a, b, p)
        faces += [(b, c, p), (c, a, p)]
    return pos, faces, 0


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    length = math.sqrt(sum(x * x for x in a))
    return tuple(x / length for x in a)


MESHES = {
    "icosahedron.obj": (make_icosahedron, "regular icosahedron, circumradius 1: 12 vertices of valence 5"),
    "tri-torus.obj": (make_torus, "12 x 8 triangulated torus (R = 2, r = 0.7), genus 1, two edge flips"),
    "tri-mix.obj": (make_mix, "heptagonal bipyramid with two capped faces: valences 3, 4, 5, 8"),
}


def write_obj(path, pos, faces, comment):
    lines = ["# " + comment, "# written by meshes/make_triangle_meshes.py"]
    lines += ["v %.6f %.6f %.6f" % p for p in pos]
    lines += ["f %d %d %d" % tuple(v + 1 for v in f) for f in faces]
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


def read_obj(path):
    pos, faces = [], []
    with open(path) as f:
        for line in f:
            w = line.split()
            if w and w[0] == "v":
                pos.append(tuple(float(x) for x in w[1:4]))
            elif w and w[0] == "f":
                faces.append(tuple(int(x) - 1 for x in w[1:]))
    return pos, faces


def check(name, pos, faces, genus):
    errors = []
    directed = Counter()
    for f in faces:
        if len(f) != 3 or len(set(f)) != 3 or any(v < 0 or v >= len(pos) for v in f):
            errors.append("bad face %s" % (f,))
            continue
        for k in range(3):
            directed[(f[k], f[(k + 1) % 3])] += 1
    for (a, b), count in directed.items():
        if count != 1 or directed.get((b, a)) != 1:
            errors.append("edge (%d, %d) is not used once each way" % (a, b))
    out_edges = defaultdict(dict)
    for f in faces:
        for k in range(3):
            out_edges[f[k]][f[(k + 1) % 3]] = f[(k + 2) % 3]
    valence = {v: len(e) for v, e in out_edges.items()}
    for v, e in out_edges.items():  # one fan: follow next neighbours round the vertex
        start = next(iter(e))
        w, seen = start, 0
        while True:
            w, seen = e[w], seen + 1
            if w == start or seen > len(e):
                break
        if seen != len(e):
            errors.append("vertex %d is not a single fan" % v)
    volume = sum(sum(a * b for a, b in zip(pos[f[0]], cross(pos[f[1]], pos[f[2]]))) for f in faces) / 6
    if volume <= 0:
        errors.append("signed volume %.6f is not positive" % volume)
    chi = len(pos) - len(directed) // 2 + len(faces)
    if chi != 2 - 2 * genus:
        errors.append("Euler characteristic %d, expected %d" % (chi, 2 - 2 * genus))
    if sum(6 - k for k in valence.values()) != 6 * chi:
        errors.append("sum of (6 - valence) is not 6 chi")
    crowded = sum(1 for f in faces if sum(valence[v] != 6 for v in f) >= 2)
    hist = ", ".join("%d: %d" % kv for kv in sorted(Counter(valence.values()).items()))
    print("%-16s %4d faces %4d vertices  valences %s  faces with >= 2 EVs: %d" % (name, len(faces), len(pos), hist, crowded))
    for e in errors:
        print("  error: " + e)
    return not errors


def main(argv):
    ok = True
    for fname, (make, comment) in MESHES.items():
        path = os.path.join(HERE, fname)
        pos, faces, genus = make()
        if "--check" not in argv:
            write_obj(path, pos, faces, comment)
        pos, faces = read_obj(path)
        ok = check(fname, pos, faces, genus) and ok
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
