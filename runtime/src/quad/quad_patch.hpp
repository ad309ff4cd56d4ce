#pragma once
// The patch of one face of a prepared quad mesh: which table evaluates it
// (regular, or the extraordinary patch of valence v), how the face's parameters
// map to the patch's (the extraordinary vertex is at patch (0,0)), and the
// mesh vertices that are its control points, in the tables' canonical order
// (docs/table-format.md).
#include <vector>

#include "mesh/uniform_topology.hpp"
#include "tables/patch_kind.hpp"
#include "stencil_runtime/exact_parameter.hpp"

namespace stencil_runtime {

struct QuadPatch {
  int valence = 4;    // the patch kind (tables/patch_kind.hpp): 4 regular (16 points), 3..64 round an interior
                      // extraordinary vertex (2v+8 points), or a boundary sector's face (its own count)
  int rotation = 0;   // face corner at patch (0,0)
  std::vector<int> points;

  // Grid indices (i/n, j/n) of the face -> grid indices of the patch.
  void to_patch(long i, long j, long n, long& pi, long& pj) const {
    switch (rotation) {
      case 0: pi = i, pj = j; break;
      case 1: pi = j, pj = n - i; break;
      case 2: pi = n - i, pj = n - j; break;
      default: pi = n - j, pj = i; break;
    }
  }
  // Patch coordinates (x, y) back to the face's (u, v): the inverse of to_patch.
  static void from_patch(int rotation, double x, double y, double& u, double& v) {
    switch (rotation) {
      case 0: u = x, v = y; break;
      case 1: u = 1 - y, v = x; break;
      case 2: u = 1 - x, v = 1 - y; break;
      default: u = y, v = 1 - x; break;
    }
  }
  // The same for an exact parameter.
  ExactParameter to_patch(const ExactParameter& p) const {
    const Fraction one{1, 1};
    switch (rotation) {
      case 0: return p;
      case 1: return {p.v, subtract(one, p.u)};
      case 2: return {subtract(one, p.u), subtract(one, p.v)};
      default: return {subtract(one, p.v), p.u};
    }
  }
};

// Whether a vertex inside the mesh is regular: in four faces and no cone
// point (`rule`: per vertex, sharp_cut.hpp).
bool regular_inside(const QuadTopology& topology, int vertex, const std::vector<SectorRule>& rule);

// Requires at most one corner of the face that is not regular_inside (the
// preparation): its patch is the interior one of that valence, or a cone
// point's (the same layout, its own kind).
QuadPatch gather_quad_patch(const QuadTopology& topology, std::size_t face, const std::vector<SectorRule>& rule);

// Faces on a mesh's boundary whose patch is regular once the points beyond
// the boundary are supplied (docs/runtime.md, "Boundaries"): the face has one
// boundary edge whose two vertices are in two faces each, or two boundary
// edges meeting at a corner in one face, their other ends in two faces each;
// its other corners are interior, of valence 4.
// The boundary curve of both quad schemes is their regular curve with the
// boundary point held, which equals the regular curve on the sequence
// reflected through the boundary point, p(-j) = 2 p(0) - p(j): the missing
// row of the 4x4 block is the "phantom" row 2 p(row 0) - p(row 1), as in
// OpenSubdiv's regular boundary patches.
// `rule`: per vertex, its sector rule (sharp_cut.hpp: a corner stays put: with
// edge-and-corner a boundary vertex in one face, any vertex Sdc's corner rule gives).
bool boundary_patch_ready(const QuadTopology& topology, std::size_t face, const std::vector<SectorRule>& rule);

// A regular patch (valence 4, rotation 0) of such a face: `points` holds the
// mesh vertices it reaches; each missing point is appended to `phantoms` as
// its row over mesh vertices, and named by its index `first_phantom +` its
// position in `phantoms`.
QuadPatch gather_boundary_patch(const QuadTopology& topology, std::size_t face, std::size_t first_phantom,
                                std::vector<std::vector<std::pair<int, double>>>& phantoms);

// Vertices on the boundary whose faces get a boundary sector's patch
// (tables/patch_kind.hpp): those in other than two faces and corners, except a
// corner in one face, whose patch is a regular one with phantom points (a dart
// is always one: the end of an infinitely sharp crease).
bool sector_vertex(const QuadTopology& topology, int vertex, const std::vector<SectorRule>& rule);

// Whether the face at such a vertex (its corner `at`) has its sector's
// patch: its other corners are regular (inside the mesh in four faces, or on
// the boundary in two, not corners, and on one of the face's boundary edges).
bool sector_patch_ready(const QuadTopology& topology, std::size_t face, int at, const std::vector<SectorRule>& rule);

// That patch: the vertex at patch (0,0) (rotation = `at`), the points in the
// sector's canonical order (docs/table-format.md, "Boundary sectors").
QuadPatch gather_sector_patch(const QuadTopology& topology, std::size_t face, int at, const std::vector<SectorRule>& rule);

}  // namespace stencil_runtime
