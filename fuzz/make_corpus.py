#!/usr/bin/env python3
"""Regenerates the fuzz fixtures (fuzz/fixtures/) and seed corpus (fuzz/corpus/)
from a built stencilgen, the bundled meshes and schemes, the hand-written seeds
below (small valid inputs and slightly broken ones: truncated, a count or field
changed) and the hand-written files under fuzz/seeds/<target>/. Run after a table format changes:

    python3 fuzz/make_corpus.py build/bin/stencilgen

Only fuzz/fixtures and fuzz/corpus are rewritten; regressions/ and found/ are
left alone."""
import pathlib
import shutil
import subprocess
import sys
import tempfile

FUZZ = pathlib.Path(__file__).resolve().parent
ROOT = FUZZ.parent


def stencilgen(exe, out, *args):
    subprocess.run([exe, *args, "--out", str(out), "-q"], check=True, stdout=subprocess.DEVNULL)


def truncated(data):
    return data[: len(data) // 2]


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    exe = sys.argv[1]
    fixtures, corpus = FUZZ / "fixtures", FUZZ / "corpus"
    shutil.rmtree(fixtures, ignore_errors=True)
    shutil.rmtree(corpus, ignore_errors=True)
    seeds = {}  # target -> {name: bytes}

    def seed(target, name, data):
        seeds.setdefault(target, {})[name] = data if isinstance(data, bytes) else data.encode()

    with tempfile.TemporaryDirectory() as tmp:
        t = pathlib.Path(tmp)
        # Fixtures: the tables the mesh target uses, and the valid JSON directory
        # whose files the quad_json_* targets mutate.
        stencilgen(exe, t / "fix", "--scheme", "nonpoly", "--valence", "3-8", "--n", "1-2")
        stencilgen(exe, t / "fix", "--scheme", "loop", "--valence", "3-8", "--n", "1-2")
        stencilgen(exe, t / "small", "--scheme", "nonpoly", "--valence", "3,5", "--n", "1-2")
        fixtures.mkdir(parents=True)
        shutil.copy(t / "fix/nonpoly/nonpoly.sgs", fixtures)
        shutil.copy(t / "fix/loop/loop.sgt", fixtures)
        json_dir = fixtures / "nonpoly-json"
        for sub in ("v3", "v5", "regular"):
            shutil.copytree(t / "small/nonpoly" / sub, json_dir / sub)
        shutil.copy(t / "small/nonpoly/descent.json", json_dir)  # subdivision and tangent stencils

        # Binary tables.
        stencilgen(exe, t / "cc", "--scheme", "catmull-clark", "--valence", "3", "--n", "1-2")
        stencilgen(exe, t / "stored", "--scheme", "nonpoly", "--valence", "3", "--n", "1-2", "--binary-layout", "stored")
        stencilgen(exe, t / "single", "--scheme", "nonpoly", "--valence", "5", "--n", "2", "--binary-precision", "single")
        stencilgen(exe, t / "small", "--scheme", "loop", "--valence", "3,5", "--n", "1-2")
        stencilgen(exe, t / "small", "--scheme", "sqrt3", "--valence", "3", "--n", "1")
        stencilgen(exe, t / "single", "--scheme", "loop", "--valence", "5", "--n", "1", "--binary-precision", "single")
        sgs = (t / "small/nonpoly/nonpoly.sgs").read_bytes()
        seed("sgs_tables", "nonpoly-v3-5-n1-2.sgs", sgs)
        seed("sgs_tables", "catmull-clark-v3-n1-2.sgs", (t / "cc/catmull-clark/catmull-clark.sgs").read_bytes())
        seed("sgs_tables", "nonpoly-v5-n2-single.sgs", (t / "single/nonpoly/nonpoly.sgs").read_bytes())
        seed("sgs_tables", "truncated.sgs", truncated(sgs))
        seed("sgs_tables", "nonpoly-v3-n1-2-stored.sgs", (t / "stored/nonpoly/nonpoly.sgs").read_bytes())
        sgt = (t / "small/loop/loop.sgt").read_bytes()
        seed("sgt_tables", "loop-v3-5-n1-2.sgt", sgt)
        seed("sgt_tables", "sqrt3-v3-n1.sgt", (t / "small/sqrt3/sqrt3.sgt").read_bytes())
        seed("sgt_tables", "loop-v5-n1-single.sgt", (t / "single/loop/loop.sgt").read_bytes())
        seed("sgt_tables", "truncated.sgt", truncated(sgt))

        # Curve tables (binary and exact JSON).
        stencilgen(exe, t / "curves", "--scheme", "fourpoint", "--n", "3")
        stencilgen(exe, t / "curves", "--scheme", "nubspline3", "--n", "2")
        stencilgen(exe, t / "curves", "--scheme", "ternary-bspline3", "--n", "2")
        for scheme, n in (("fourpoint", 1), ("fourpoint", 3), ("nubspline3", 2), ("ternary-bspline3", 2)):
            seed("sgc_curve", f"{scheme}-n{n}.sgc", (t / "curves" / scheme / f"n{n}.sgc").read_bytes())
            seed("curve_table_json", f"{scheme}-n{n}.json", (t / "curves" / scheme / f"n{n}.json").read_bytes())
        fourpoint3 = (t / "curves/fourpoint/n3.sgc").read_bytes()
        seed("sgc_curve", "truncated.sgc", truncated(fourpoint3))
        curve_json = (t / "curves/fourpoint/n3.json").read_text()
        seed("curve_table_json", "truncated.json", curve_json[: len(curve_json) // 2])
        seed("curve_table_json", "off-grid-key.json", curve_json.replace('"1/3":', '"1/4":', 1))

        # JSON quad table directories: an input without "@@ " replaces the default file.
        v3n1 = (json_dir / "v3/n1.json").read_text()
        v5n2 = (json_dir / "v5/n2.json").read_text()
        seed("quad_json_table", "v3-n1.json", v3n1)
        seed("quad_json_table", "v3-n2-as-n1.json", (json_dir / "v3/n2.json").read_text())
        seed("quad_json_table", "truncated.json", v3n1[: len(v3n1) // 2])
        seed("quad_json_table", "two-files", "@@ v3/n2.json\n" + (json_dir / "v3/n2.json").read_text() +
             "@@ v5/n1.json\n" + (json_dir / "v5/n1.json").read_text())
        regular4 = (json_dir / "regular/n4.json").read_text()
        seed("quad_json_regular", "regular-n4.json", regular4)
        seed("quad_json_regular", "regular-n2-as-n4.json", (json_dir / "regular/n2.json").read_text())
        seed("quad_json_regular", "truncated.json", regular4[: len(regular4) // 2])
        seed("quad_json_regular", "two-files", "@@ regular/n2.json\n" + (json_dir / "regular/n2.json").read_text() + "@@ regular/n4.json\n" + regular4)
        descent = (json_dir / "descent.json").read_text()
        seed("quad_json_descent", "descent.json", descent)
        seed("quad_json_descent", "truncated.json", descent[: len(descent) // 2])
        seed("quad_json_descent", "version-1.json", descent.replace('"version":3', '"version":1', 1))
        seed("quad_json_descent", "version-2.json", descent.replace('"version":3', '"version":2', 1))
        seed("quad_json_descent", "sector-out-of-range.json", descent.replace('"faces":3,"position":1', '"faces":3,"position":7', 1))
        seed("quad_json_descent", "no-tangents.json", descent.replace('"tangents":{', '"tangents":null,"x":{', 1))
        for name in ("v3/n1.json", "v5/n2.json"):
            seed("surface_table_verify", name.replace("/", "-"), (json_dir / name).read_text())
        seed("surface_table_verify", "v5-n2-wrong-weight.json", v5n2.replace('"numerators":["45"', '"numerators":["46"', 1))

    # Meshes.
    for name in ("cube.obj", "icosahedron.obj", "tri-mix.obj", "torus-3-5.obj"):
        seed("obj_mesh", name, (ROOT / "meshes" / name).read_bytes())
    cube = (ROOT / "meshes/cube.obj").read_text()
    seed("obj_mesh", "cube-negative-indices.obj", cube.replace("f 1 3 7 5", "f -8 -6 -2 -4"))
    seed("obj_mesh", "cube-slashes.obj", cube.replace("f 1 3 7 5", "f 1/1/1 3/2/1 7//1 5/4"))
    seed("obj_mesh", "cube-open.obj", cube.replace("f 5 7 8 6\n", ""))
    seed("obj_mesh", "cube-flipped-face.obj", cube.replace("f 1 3 7 5", "f 5 7 3 1"))
    seed("obj_mesh", "cube-bad-index.obj", cube.replace("f 1 3 7 5", "f 1 3 7 9"))
    seed("obj_mesh", "pyramid-polygons.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\n"
         "f 4 3 2 1\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n")
    seed("obj_mesh", "short-vertex.obj", "v 1 2\nf 1 1 1\n")
    # OpenSubdiv's tag lines: inert ones, refused ones, malformed ones.
    seed("obj_mesh", "cube-inert-tags.obj", cube + "t crease 2/1/0 0 1 0\nt interpolateboundary 1/0/0 2\n"
         "t creasemethod 0/0/1 chaikin\nt smoothtriangles 0/0/1 catmark\nt unknown 0/0/0\n")
    seed("obj_mesh", "cube-crease.obj", cube + "t crease 3/2/0 0 1 3 2.5 0.5\nt corner 1/1/0 7 4\nt hole 1/0/0 2\n")
    seed("obj_mesh", "cube-bad-tags.obj", cube + "t crease 2/1/0 0 6 1\nt corner 9/1 1\n")

    # A vertex on the boundary in three faces (a boundary sector's patch), edge only.
    seed("obj_mesh", "fan-3-edge-only.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0.2\nv 0 1 0\nv -1 1 0.1\nv -1 0 0\nv -1 -1 0.3\nv 0 -1 0\n"
         "f 1 2 3 4\nf 1 4 5 6\nf 1 6 7 8\n")
    # Hand-written files.
    for path in sorted((FUZZ / "seeds").glob("*/*")):
        seed(path.parent.name, path.name, path.read_bytes())

    # Scheme files.
    for path in sorted((ROOT / "schemes").glob("*.json")):
        text = path.read_text()
        kind = {"quad": "quad_scheme", "triangle": "triangle_scheme"}.get(
            text.split('"type": "')[1].split('"')[0], "curve_scheme")
        seed(kind, path.name, text)
    fourpoint = (ROOT / "schemes/fourpoint.json").read_text()
    seed("curve_scheme", "fourpoint-no-mask.json", fourpoint.split('"mask"')[0].rstrip().rstrip(",") + "\n}\n")
    seed("curve_scheme", "fourpoint-float.json", fourpoint.replace('"1/16"', "0.0625"))
    nonpoly = (ROOT / "schemes/nonpoly.json").read_text()
    seed("quad_scheme", "nonpoly-unknown-curve.json", nonpoly.replace('"nonpoly-curve"', '"no-such-curve"'))
    loop = (ROOT / "schemes/loop.json").read_text()
    seed("triangle_scheme", "loop-bad-edge.json", loop.replace('"3/8"', '"1/4"', 1))

    # Short texts.
    for k, text in enumerate(["fourpoint\nw=1/32", "nonpoly\n", "catmull-clark\n", "loop\n", "sqrt3\n",
                              "fourpoint\nw=1/0", "fourpoint\nq=1", "fourpoint\nw", "nubspline3\n"]):
        seed("scheme_param", f"seed{k}", text)
    for k, text in enumerate(["1/2 + w", "3/(2*v)", "(4 - 2*cos2pi(1/v))/9", "(5/8 - (3/8 + cos2pi(1/v)/4)^2)/v",
                              "2^-3", "-w^2", "1/0", "cos2pi(1/7)", "((1)", "x", "0^-1", "12345678901234567890/3"]):
        seed("expression", f"seed{k}", text)
        seed("expression_real", f"seed{k}", text)
    for k, text in enumerate(["0", "1", "1/3", "2/4", "-1/2", "3/2", "1/0", "1/-3", "abc", " 1/3", "1/3x",
                              "9223372036854775807/9223372036854775807"]):
        seed("parameter", f"seed{k}", text)
    for k, text in enumerate(["1\n2\n3\n", "# rates\n4\n\n5 # five\n", "0\n", "5000\n", "abc\n", "1 2\n", "7"]):
        seed("rates_file", f"seed{k}", text)
    points_seeds = ["\x00" + "0 0 0\n1 2 3\n# c\n\n4 5 6\n", "\x00" + "1 2\n", "\x00" + "1 nan 2\n",
                    "\x02" + "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "\x02" + "OFF\n99999999 0 0\n",
                    "\x02" + "OFF\n2 0 0\n0 0 0\n",
                    "\x01" + "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                    "property float z\nend_header\n0 0 0\n1 1 1\n",
                    "\x01" + "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty double x\n"
                    "property double y\nproperty double z\nend_header\n" + "\x00" * 24,
                    # Elements after the points: walked, not read (ASCII lines, binary lists).
                    "\x01" + "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                    "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                    "\x01" + "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
                    "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                    "property uchar flag\nend_header\n" + "\x00" * 12 + "\x03" + "\x00" * 12 + "\x01"]
    for k, text in enumerate(points_seeds):
        seed("points_file", f"seed{k}", text)
    for k, text in enumerate(["24", "12-24", "3,5,7", "1-4,8", "", "0", "5-3", "1,,2", "1234567", "3-8"]):
        seed("rate_spec", f"seed{k}", text)

    total = 0
    for target, files in sorted(seeds.items()):
        for name, data in files.items():
            path = corpus / target / name
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_bytes(data)
            total += len(data)
    fixture_bytes = sum(p.stat().st_size for p in fixtures.rglob("*") if p.is_file())
    print(f"{sum(len(f) for f in seeds.values())} seeds for {len(seeds)} targets, {total} bytes; fixtures {fixture_bytes} bytes")


if __name__ == "__main__":
    main()
