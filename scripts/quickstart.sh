#!/usr/bin/env bash
# The README's first command: install what is missing, build, and run the main
# job on a bundled default: exact surface tables of the non-polynomial quad scheme
# around extraordinary vertices of valence 3..8 at rates 1..24, its smoothness
# analysis, a watertight view-dependent adaptive tessellation of the bundled chess
# piece from those tables, exact tables for every shipped curve scheme (rates
# 1..24, each verified), and a plot of the four-point scheme at n = 21.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build -j"$(nproc)"
./build/bin/stencilgen --scheme nonpoly --valence 3-8 --n 24 --out tables
./build/bin/stencilgen analyze --scheme nonpoly --valence 3-8 --samples 16 | grep -E '^(valence|all|[0-9])'
./build/bin/stenciltess --tables tables/nonpoly --mesh meshes/chess-piece.obj \
  --camera 3,-5,3,0,0,1.2 --pixels 6 --out tables/chess-piece.ply
for scheme in $(./build/bin/stencilgen list | awk '/\(curve\)/ {print $1}'); do
  ./build/bin/stencilgen --scheme "$scheme" --n 24 --out tables --quiet
done
./build/bin/stencilgen verify tables/fourpoint/n3.json
./build/bin/stencilgen plot --scheme fourpoint --n 21 --out tables/fourpoint-n21.svg
echo "Tessellation: $(pwd)/tables/chess-piece.ply (closed, watertight, one exact limit point per vertex)."
echo "Tables are in $(pwd)/tables/: nonpoly/v<V>/n<N>.json (exact surface stencils), nonpoly/nonpoly.sgs (binary),"
echo "<curve scheme>/n<N>.json and .sgc; see docs/table-format.md."
