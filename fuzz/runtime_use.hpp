#pragma once
// What the runtime's tools (stencileval, stenciltess) do with loaded tables and
// meshes, for the fuzz targets of the table and mesh readers: many faults of a
// reader show only when the data it accepted is used (an index that passes the
// loader and is out of range at lookup, a table with no rates). Each function
// throws what the library throws; work is bounded so that a small input cannot
// ask for hours of lookups.
#include <memory>

#include "stencil_runtime/mesh.hpp"
#include "stencil_runtime/tables.hpp"

namespace fuzz {

// Every stored stencil through the public lookups (every valence, rate and grid
// index, within a work budget), into buffers sized exactly as documented; then
// the bundled cube (valence 3) and icosahedron (polygon rules, valence 5)
// prepared, tessellated at rate 1 snapped to the tables, and evaluated at a few
// grid points of every rate.
// Quad tables (Tables::quad()); triangle tables (Tables::triangle()) the same
// way with the bundled icosahedron (valence 5). The surface is built through
// the public interface (SurfaceTopology, Surface, TessellationPlan).
void use_tables(const std::shared_ptr<const stencil_runtime::Tables>& tables);

// A control mesh as stenciltess takes it: curvature and view rates, then the
// surface with the fixture tables (fuzz/fixtures: nonpoly.sgs for quads and
// polygons, loop.sgt for triangles), tessellated at those rates snapped to the
// tables, and evaluated at a few points of each original face.
void use_mesh(const stencil_runtime::Mesh& mesh);

}  // namespace fuzz
