#!/usr/bin/env bash
# OpenSubdiv's own regression shapes (catmark_* and loop_*, 118 meshes with
# boundaries, creases, corners, holes, Chaikin creasing, non-manifold vertices,
# valence-2 vertices and poles) through the runtime, against Bfr, and the
# Catmull-Clark ones under nonpoly too, checked for continuity across edges:
#
#   scripts/opensubdiv-shapes.sh OPENSUBDIV_SOURCE [VALENCES]
#
# OPENSUBDIV_SOURCE is a checkout of https://github.com/PixarAnimationStudios/OpenSubdiv
# (the shapes are C++ headers under regression/shapes/; they are not bundled
# here, and Debian's packages do not ship them). VALENCES (default 3-12) is
# what the tables are generated for; shapes with other valences are refused
# with the stencilgen call that covers them. Prints a Markdown table (one row
# per shape, tests/opensubdiv_shapes.cpp says what is compared) and exits 1 if
# any sample disagrees. Builds into build/ (Release); scratch files go to a
# temporary directory that is removed afterwards.
set -euo pipefail
[ $# -ge 1 ] && [ $# -le 2 ] || { echo "usage: scripts/opensubdiv-shapes.sh OPENSUBDIV_SOURCE [VALENCES]" >&2; exit 2; }
source_dir="$1"
valences="${2:-3-12}"
shapes_dir="$source_dir/regression/shapes"
[ -d "$shapes_dir" ] || { echo "opensubdiv-shapes.sh: $shapes_dir is not a directory (give an OpenSubdiv source tree)" >&2; exit 2; }
cd "$(dirname "$0")/.."

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build -j"$(nproc)" --target stencilgen check_opensubdiv_shapes > /dev/null

scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
count=0
for header in "$shapes_dir"/catmark_*.h "$shapes_dir"/loop_*.h; do
  [ -f "$header" ] || continue
  name="$(basename "$header" .h)"
  # Each line of the OBJ text is a string literal "...\n" on a line of its own.
  sed -n 's/^[[:space:]]*"\(.*\)\\n"[[:space:]]*$/\1/p' "$header" > "$scratch/$name.obj"
  [ -s "$scratch/$name.obj" ] || { echo "opensubdiv-shapes.sh: no OBJ text found in $header" >&2; exit 1; }
  count=$((count + 1))
done
[ "$count" -gt 0 ] || { echo "opensubdiv-shapes.sh: no catmark_*.h or loop_*.h in $shapes_dir" >&2; exit 1; }
echo "opensubdiv-shapes.sh: $count shapes; tables for valences $valences, rates 1..4" >&2

build/bin/stencilgen --scheme catmull-clark --valence "$valences" --n 4 --out "$scratch/tables" --quiet >&2
build/bin/stencilgen --scheme loop --valence "$valences" --n 4 --out "$scratch/tables" --quiet >&2
build/bin/stencilgen --scheme nonpoly --valence "$valences" --n 4 --out "$scratch/tables" --quiet >&2
build/bin/check_opensubdiv_shapes "$scratch/tables/catmull-clark/catmull-clark.sgs" "$scratch/tables/loop/loop.sgt" \
  --nonpoly "$scratch/tables/nonpoly/nonpoly.sgs" "$scratch"/*.obj
