#pragma once
// The topology of a control mesh under a scheme's tables, built once from face
// sizes and face-vertex indices alone (no positions), like OpenSubdiv's
// Far::TopologyRefiner and Bfr::SurfaceFactory. It holds everything that does
// not depend on positions: the polygon step and the isolation steps as a
// sparse refinement matrix (prepared vertices = R * control vertices), every
// prepared face's patch, and what each face's (u, v) means. Surfaces
// (surface.hpp) and tessellation plans (tessellation.hpp) share it; it shares
// the tables, so nothing it refers to can be freed before it.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "exact_parameter.hpp"
#include "face_domain.hpp"
#include "mesh.hpp"
#include "stencil_rows.hpp"
#include "tables.hpp"

namespace stencil_runtime {

class Family;  // the scheme family's own topology (below this interface)

// A face and an exact parameter on it.
struct Sample {
  std::size_t face = 0;
  ExactParameter at;
};

// A face and a real parameter on it.
struct RealSample {
  std::size_t face = 0;
  double u = 0, v = 0;
};

class SurfaceTopology {
 public:
  // Checks the faces (sizes 3..limits::kMaxFaceSize, indices below
  // vertex_count, no vertex twice in a face) and the valences against the
  // tables, then prepares. Boundaries are allowed for every scheme but
  // sqrt(3); vertices in no face are left out; non-manifold vertices and edges
  // are cut into manifold pieces with infinitely sharp corners and edges, as
  // OpenSubdiv does (docs/runtime.md). The preparation: the scheme's polygon step
  // when a quad scheme's mesh has other polygons, and whole-mesh refinement
  // steps until every face's patch is in the tables' form (at most
  // limits::kMaxRefinementSteps). Throws MeshError naming the face, edge or
  // vertex (numbered from 0 in file order; OBJ's are from 1), with the
  // stencilgen call that adds a missing valence.
  //
  // `holes`: faces without a surface (OpenSubdiv's `hole` tag). They still
  // take part in the subdivision of their neighbours (the surface round a hole
  // is the one without the tag, as in OpenSubdiv), but evaluating them is an
  // error naming the face and tessellations leave them out, their rims
  // becoming boundaries of the output. Throws MeshError for an index out of
  // range or when every face is a hole.
  //
  // `features`: semi-sharp creases and corners (OpenSubdiv's rules, either crease
  // method): the preparation applies whole-mesh steps with the sharp rules
  // until every sharpness has decayed (ceil of the largest), the crease rule
  // being the scheme's own curve (a quad scheme's regular curve; a Loop
  // scheme's crease_curve); the surface is then smooth and evaluated exactly
  // from the tables. A sharpness of 10 or more is infinitely sharp, as in
  // OpenSubdiv: the patches of the mesh cut along such creases (crease,
  // corner, dart and cone sectors from the tables). Throws MeshError for an
  // edge or vertex the mesh lacks, a sharpness that is negative or not
  // finite, too many steps (limits::kMaxCreaseStepFaces), or tables without a
  // crease rule (sqrt(3)). Two entries for one edge or vertex: the last wins.
  // `features.smooth_triangles` (OpenSubdiv's TRI_SUB_SMOOTH) changes the
  // polygon step's edge points next to triangles; it needs Catmull-Clark's
  // polygon edge rule (MeshError otherwise) and has no effect on Loop.
  static std::shared_ptr<const SurfaceTopology> create(std::shared_ptr<const Tables> tables, std::size_t vertex_count,
                                                       std::vector<int> face_sizes, std::vector<int> face_vertices,
                                                       const std::vector<int>& holes = {}, const MeshFeatures& features = {});
  // The same from a mesh read from a file, with its tags: holes, creases,
  // corners, the boundary interpolation, the crease method and smooth
  // triangles as above. What the runtime cannot honour is refused with a
  // MeshError naming the file and line of the tag (the surface would be
  // silently wrong): creases and corners on sqrt(3), and `smoothtriangles` on
  // a quad scheme without Catmull-Clark's polygon edge rule. Boundary
  // interpolation has no effect on a closed mesh.
  static std::shared_ptr<const SurfaceTopology> create(std::shared_ptr<const Tables> tables, const Mesh& mesh);

  const Tables& tables() const { return *tables_; }
  const std::shared_ptr<const Tables>& shared_tables() const { return tables_; }
  std::size_t vertex_count() const { return vertex_count_; }
  std::size_t face_count() const { return face_sizes_.size(); }
  const std::vector<int>& face_sizes() const { return face_sizes_; }
  const std::vector<int>& face_vertices() const { return face_vertices_; }
  // Whether another mesh has exactly this connectivity (an animation frame).
  bool same_connectivity(std::size_t vertex_count, const std::vector<int>& face_sizes,
                         const std::vector<int>& face_vertices) const;

  // Throws EvaluationError for a face that does not exist or is a hole (every
  // evaluation asks for the domain first).
  FaceDomain domain(std::size_t face) const;
  bool is_hole(std::size_t face) const { return face < holes_.size() && holes_[face] != 0; }
  bool has_holes() const { return !holes_.empty(); }
  // Whether the mesh has boundary edges (an open surface: no inside, like one with holes).
  bool has_boundary() const;
  // Per prepared face: whether it covers part of a hole (empty when none is).
  std::vector<char> prepared_holes() const;

  // The preparation: steps applied ("1 subdivision step", "2 double sqrt(3)
  // steps", "the polygon step and 1 subdivision step"), and the prepared mesh's size.
  std::string preparation() const;
  int refinement_steps() const;
  std::size_t prepared_face_count() const;
  std::size_t prepared_vertex_count() const;

  // The limit point at an exact parameter as a sparse row over the control
  // vertices, wherever it is exact: the tables hold the parameter, or the
  // patch's descent through the scheme's own subdivision reaches a parameter
  // they hold or a regular patch whose basis is polynomial (Catmull-Clark and
  // Loop: every parameter). Throws EvaluationError naming the face and
  // parameter otherwise (a non-polynomial scheme between its grids: evaluate
  // within a tolerance with Surface::evaluate instead).
  StencilRows stencil(std::size_t face, const ExactParameter& at) const;
  // One row per sample (rows computed in parallel).
  StencilRows stencils(const std::vector<Sample>& samples) const;
  // The same at real parameters (a double is an exact binary fraction).
  StencilRows stencil(std::size_t face, double u, double v) const;
  StencilRows stencils(const std::vector<RealSample>& samples) const;

  const Family& family() const { return *family_; }
  ~SurfaceTopology();

 private:
  SurfaceTopology();
  std::shared_ptr<const Tables> tables_;
  std::size_t vertex_count_ = 0;
  std::vector<int> face_sizes_, face_vertices_;
  std::vector<char> holes_;  // per face, or empty when the mesh has none
  std::unique_ptr<const Family> family_;
};

}  // namespace stencil_runtime
