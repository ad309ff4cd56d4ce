#pragma once
// A face at a boundary vertex of a Loop mesh, as a patch of its own: the
// vertex B in k faces (its sector), the face at position p among them
// (common/sector_kind.hpp), after isolation (every other vertex the patch
// reaches is regular: valence 6 inside, three faces on the boundary).
//
// Chart: k wedges of the triangular lattice round B, in the frames of
// sector_chart.hpp (wedge t holds a (1,0) + b (1,1), a >= 1, 0 <= b < a, in
// its own frame; e_t = (1,0) of frame t), not closed: ray 0 (frame 0's b = 0)
// and ray k (frame k's b = 0) are the boundary, e_0 and e_k on them. Beyond
// each ray the chart holds one row of phantom points, each the point across a
// boundary edge (b1, b2) from the real triangle (b1, b2, r) there:
// b1 + b2 - r. With them Loop's regular rules give its boundary rules exactly
// (docs/runtime.md, "Loop with boundaries"), so every child of the patch but
// B's own is the regular box spline over its 12 points.
//
// The patch of face p has B at (0,0), u towards e_p, v towards e_{p+1}; its
// point (u, v) lies at (u + v, v) in frame p (as triangle_patch.hpp's).
//
// A cone point (an infinitely sharp vertex inside the mesh on no infinitely
// sharp edge) is B held in place with everything round it smooth: the closed
// ring of k wedges (BoundaryWedge's `closed`), every face alike, so only
// position 0 is made; its layout has e_0..e_{k-1} (no ray k).
//
// Rules: inside, the scheme's regular ones; along the rays the crease curve
// (vertex crease_centre, crease_neighbour; edge midpoint); B follows the crease
// curve over e_0 and e_k (Crease), stays put (Corner), or follows the scheme's
// smooth rule at valence k over e_0..e_{k-1} (Dart). A dart is the same chart
// with rays 0 and k the two sides of its slit: the infinitely sharp crease that
// ends at B, cut open (the runtime gathers the same mesh points on both, as it
// gathers the copies the cut makes). The slit's modes (ray k minus ray 0) are
// zero on any mesh and do not reach the rest: the subspace with equal sides is
// kept by A0, so W(x) there is the dart's surface. The crease and corner rules
// are rational, so their stencils are exact; a dart's are where Loop's smooth
// rule is (valence 3, 4, 6), and in 80 digits with residuals elsewhere.
//
// Method (as the quad sectors): with A0 the one-step matrix of the patch's
// points onto its child at B, W(x) = W(2x) A0 for x in that child
// (u + v <= 1/2), the regular box spline over the refined points elsewhere,
// and W(0) the left eigenvector of A0 for the eigenvalue 1.
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "algebra/rational.hpp"
#include "algebra/tangent_stencils.hpp"
#include "common/sector_kind.hpp"
#include "triangle/bivariate_solver.hpp"
#include "triangle/sector_chart.hpp"
#include "triangle/triangle_scheme.hpp"

namespace sg {

// A point of the chart in canonical form: B is (0, 0, 0); a real point is in
// wedge 0..k-1 (a >= 1, 0 <= b < a) or on ray k (sector k, a >= 1, b = 0); a
// phantom is below ray 0 (sector 0, a >= 0, b = -1) or beyond ray k (sector k,
// a >= 1, b = 1).
struct WedgePoint {
  int sector = 0;
  long a = 0, b = 0;
  auto operator<=>(const WedgePoint&) const = default;
};

// `closed`: a cone point's chart instead, the whole ring of k wedges round B
// (frame k is frame 0 again; no rays, no phantoms).
class BoundaryWedge {
 public:
  explicit BoundaryWedge(int faces, bool closed = false);
  int faces() const { return k_; }
  bool closed() const { return closed_; }
  // The lattice point (a, b) of frame `sector` in canonical form; nullopt when
  // it lies beyond the phantom rows.
  std::optional<WedgePoint> canonical(int sector, long a, long b) const;
  bool phantom(const WedgePoint& p) const { return !closed_ && ((p.sector == 0 && p.b < 0) || (p.sector == k_ && p.b > 0)); }
  // A phantom's b1, b2 and r (it is b1 + b2 - r), all real.
  std::array<WedgePoint, 3> phantom_parts(const WedgePoint& p) const;
  // B, or a point on ray 0 or ray k.
  bool on_boundary(const WedgePoint& p) const { return p.b == 0 && (p.a == 0 || (!closed_ && (p.sector == 0 || p.sector == k_))); }

 private:
  int k_;
  bool closed_;
};

// T: Rational (exact) or Real (80 digits: a dart where Loop's smooth rule is irrational).
template <class T = Rational>
struct TriangleSectorPatch {
  BoundarySector sector;
  long grid = 1;
  std::vector<WedgePoint> layout;         // the control points: B, e_0..e_k, then by (a, sector, b)
  std::vector<std::vector<T>> stencils;  // W(i/g, j/g) over `layout`, index j * (g + 1) + i, i + j <= g
  // A0: the refined points at the layout's positions (the child at B) over the layout.
  std::vector<std::vector<std::pair<std::size_t, T>>> child_at_vertex;
  T eigen_residual = 0;  // max |W(0) A0 - W(0)| (zero when exact)
  const std::vector<T>& at(long i, long j) const { return stencils[static_cast<std::size_t>(j * (grid + 1) + i)]; }
};

// Whether the sector's rules are rational (every kind but a dart at a valence
// where the scheme's smooth rule is irrational).
bool exact_triangle_sector(const TriangleScheme& scheme, const BoundarySector& sector);

// The patch of `sector` at the grid g; `regular` is the regular scaling
// function on (1/g)Z^2 (solve_regular). Loop schemes only; T = Rational
// throws sg::Error where the rules are irrational (exact_triangle_sector).
template <class T = Rational>
TriangleSectorPatch<T> solve_triangle_sector(const TriangleScheme& scheme, const BoundarySector& sector, long g,
                                             const BivariateSolution& regular);

// The tangent plane at B of a crease sector's patch (algebra/tangent_stencils.hpp,
// boundary_tangent_stencils): the two leading eigenvalues of A0 below 1 with a
// regular characteristic map on the patch, whose eigenvectors hold the
// boundary curve's tangent e_k - e_0. A dart's: those of A0 with the slit
// folded shut (ray k's points onto ray 0's), no boundary curve to hold; its
// stencils are 0 on ray k. `patch` at any grid g >= 2 (its corner stencils
// give the edges' far ends, its grid the map's cells). Nothing, with `why`,
// for a corner (no tangent plane) or where the spectrum gives none.
template <class T>
std::optional<TangentStencils> triangle_sector_tangents(const TriangleSectorPatch<T>& patch, std::string& why);

// A weight the tables keep: its value (rounded into the binary tables) and
// its text for the exact JSON: "p/q" where the sector's rules are rational,
// else 40 significant digits of the 80-digit solve.
struct SectorWeight {
  Real value;
  std::string text;
};
using SectorRows = std::vector<std::vector<std::pair<std::size_t, SectorWeight>>>;

// What the tables keep of a sector's patch: no stencils (every rate of every
// sector would be large); the runtime makes them from this by the same
// recursion (docs/table-format.md, "Loop boundary sectors").
struct TriangleSectorDescent {
  BoundarySector sector;
  std::vector<WedgePoint> layout;
  bool exact = true;                // rational rules: every weight below is exact
  Real eigen_residual = 0;          // of `limit` (zero when exact)
  std::vector<SectorWeight> limit;  // W(0)
  // The four cells of one Loop step in the order of triangle_children.hpp: the
  // child at B (A0, rows over `layout` in `layout`'s order), then the regular
  // cells, up (1, 0), up (0, 1) and down (0, 0), each unrotated: per point of
  // valence 6's layout (as the tables store it), its row over `layout`.
  SectorRows child_at_vertex;
  std::array<SectorRows, 3> regular_children;
  std::optional<TangentStencils> tangents;  // none for a corner, or where the spectrum gives no plane
  std::string no_tangents;                  // why not
};
TriangleSectorDescent triangle_sector_descent(const TriangleScheme& scheme, const BoundarySector& sector,
                                              const std::vector<SectorPoint>& regular_layout);

// The sectors the runtime needs for boundary vertices in 1..max_faces faces:
// every position of every k but 3 (in three faces the patches are regular,
// with phantoms), as Crease; with `sharp`, also Corner in every k, Dart at
// valences 3..max_faces and Cone (position 0) at valences 3..max_faces.
std::vector<BoundarySector> triangle_sectors(int max_faces, bool sharp);

}  // namespace sg
