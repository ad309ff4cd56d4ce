#!/bin/bash
# CGAL's bundled meshes (Debian's libcgal-demo: /usr/share/doc/libcgal-dev/data.tar.gz,
# 138 OFF meshes) through the runtime against OpenSubdiv, as real inputs we did
# not make: each mesh of at most MAX_FACES faces is converted to OBJ and run
# through check_opensubdiv_shapes under Catmull-Clark (every mesh) and Loop (the
# all-triangle ones): every rate-4 node and three random parameters per face
# against Bfr, and closest points against brute force (docs/robustness.md).
#
#   scripts/cgal-meshes.sh [OUT_DIR [VALENCES [MAX_FACES]]]   # defaults /tmp/cgal-meshes 3-16 3000
#
# Needs the Release build (build/) and the data archive; nothing is written
# outside OUT_DIR. Meshes with valences outside VALENCES are refused with the
# stencilgen call that covers them.
set -euo pipefail
out=${1:-/tmp/cgal-meshes}
valences=${2:-3-16}
max_faces=${3:-3000}
root=$(cd "$(dirname "$0")/.." && pwd)
archive=/usr/share/doc/libcgal-dev/data.tar.gz
[ -f "$archive" ] || { echo "cgal-meshes.sh: $archive is missing (apt-get install libcgal-demo)" >&2; exit 1; }
mkdir -p "$out/shapes"
tar -xzf "$archive" -C "$out" data/meshes
for off in "$out"/data/meshes/*.off; do
  name=$(basename "$off" .off)
  # OFF (or COFF/NOFF): a header, the counts (on the header's line or the next),
  # one vertex per line (x y z, then colours or normals), one face per line
  # (k i1 .. ik, then colours); '#' starts a comment.
  awk -v obj="$out/shapes/catmark_$name.obj" -v max="$max_faces" '
    { sub(/#.*/, ""); if (NF == 0) next }
    state == 0 { if ($1 !~ /OFF$/) { bad = 1; exit } state = 1; if (NF > 1) { $1 = ""; $0 = $0 } else next }
    state == 1 { nv = $1; nf = $2; if (nf > max) { bad = 1; exit } state = 2; next }
    state == 2 && v < nv { lines[++n] = "v " $1 " " $2 " " $3; ++v; next }
    state == 2 && f < nf { s = "f"; for (i = 2; i <= $1 + 1; ++i) s = s " " ($i + 1); lines[++n] = s; ++f; if ($1 != 3) quads = 1; next }
    END { if (bad || n == 0 || f < nf) exit 1; for (i = 1; i <= n; ++i) print lines[i] > obj; exit quads ? 2 : 0 }
  ' "$off" && status=0 || status=$?
  case $status in
    0) cp "$out/shapes/catmark_$name.obj" "$out/shapes/loop_$name.obj" ;;  # triangles: Loop too
    2) ;;
    *) rm -f "$out/shapes/catmark_$name.obj" ;;  # too large, or not an OFF mesh
  esac
done
echo "cgal-meshes.sh: $(ls "$out/shapes" | wc -l) shapes (Catmull-Clark and Loop) of at most $max_faces faces" >&2
for scheme in catmull-clark loop; do
  "$root/build/bin/stencilgen" --scheme $scheme --valence "$valences" --n 4,8 --out "$out/tables" --quiet
done
"$root/build/bin/check_opensubdiv_shapes" "$out/tables/catmull-clark/catmull-clark.sgs" "$out/tables/loop/loop.sgt" \
  "$out"/shapes/*.obj
