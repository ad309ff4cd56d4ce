#pragma once
// A closed triangle mesh under a triangle scheme's tables (Loop, sqrt(3)),
// prepared (docs/runtime.md): whole-mesh Loop steps, or double sqrt(3) steps
// that split every face in nine, until every face's patch (the regular one,
// an extraordinary vertex's, or sqrt(3)'s band region) can be gathered by
// chart walks; exact evaluation from the tables and the tessellation kernels
// (triangle_tessellation.cpp).
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>
#include <optional>
#include <utility>
#include <vector>

#include "family/crease_step.hpp"
#include "family/family.hpp"
#include "family/feature_tree.hpp"
#include "mesh/connectivity.hpp"
#include "mesh/uniform_topology.hpp"
#include "stencil_runtime/tables.hpp"
#include "tables/triangle_tables.hpp"
#include "chart_patch.hpp"
#include "face_derivative_rows.hpp"
#include "triangle_descent.hpp"

namespace stencil_runtime {

class TriangleFamily final : public Family {
 public:
  // Throws MeshError naming the face, edge or vertex (see SurfaceTopology::create).
  // `sharp`: semi-sharp creases and corners (Loop only), resolved by whole-mesh
  // Loop steps with OpenSubdiv's creasing rules (family/crease_step.hpp).
  TriangleFamily(std::shared_ptr<const Tables> tables, const Connectivity& mesh, const MeshFeatures& sharp = {});

  std::string preparation() const override;
  bool has_boundary() const override { return topology_.has_boundary(); }
  bool on_boundary(int vertex) const override { return topology_.on_boundary(vertex); }
  int refinement_steps() const override { return steps_; }
  FaceDomain domain(std::size_t face) const override;
  bool stencil(std::size_t face, const ExactParameter& at, PatchStencil& out) const override;
  using Family::stencil;  // and at a real parameter
  Approximation evaluate(std::size_t face, const ExactParameter& at, double tolerance, const Point* prepared) const override;
  Approximation evaluate(std::size_t face, double u, double v, double tolerance, const Point* prepared) const override;
  // First derivatives along the face's (u, v) anywhere but an extraordinary
  // vertex: Loop (polynomial regular patch) at any parameter; sqrt(3) exactly
  // at the parameters its tables' grids hold (version 6 tables), refused elsewhere.
  Derivatives derivatives(std::size_t face, const ExactParameter& at, const Point* prepared) const override;
  Derivatives derivatives(std::size_t face, double u, double v, const Point* prepared) const override;
  // The unit normal: the derivatives' where they exist (Loop), and at an
  // extraordinary vertex from the tables' tangent stencils (version 4 tables;
  // Loop and sqrt(3)).
  Point normal(std::size_t face, const ExactParameter& at, const Point* prepared) const override;
  Point normal(std::size_t face, double u, double v, const Point* prepared) const override;
  // Second derivatives along (u, v) (Loop only; sqrt(3) refused).
  SecondDerivatives second_derivatives(std::size_t face, const ExactParameter& at, const Point* prepared) const override;
  SecondDerivatives second_derivatives(std::size_t face, double u, double v, const Point* prepared) const override;
  // Sub-patches (closest points, triangle_sub_patches.cpp): a triangle of the
  // patch's parameters, its kind the valence and region, kind =
  // valence + (kMaxValence + 1) region; split into the tables' cells (Loop 4,
  // sqrt(3) 9). Exact derivatives in them for Loop (not at the EV itself);
  // sqrt(3) has none (the search then takes differences).
  bool hull_bounds() const override;
  void root(std::size_t prepared_face, const Point* prepared, SubPatch& out) const override;
  int split(const SubPatch& in, SubPatch* children) const override;
  Approximation evaluate(const SubPatch& in, double x, double y, double tolerance) const override;
  FaceParameterReal original(std::size_t prepared_face, double x, double y) const override;
  bool derivatives(const SubPatch& in, double& x, double& y, Derivatives& out) const override;
  const AffineParameters* affine_parameters(int kind) const override;
  const PolynomialPatch* polynomial_patch(int kind) const override;
  // Kinds up to max_kind are valences and regions; a Loop boundary sector's
  // kind is its code (TriangleTables::sector_code), beyond them, with no
  // affine enclosure or convexity bound. Its sub-patches' points are its
  // layout's followed by the eight corners of a box that holds its surface
  // (TriangleTables::sector_spread), so that their hull bounds it.
  int max_kind() const override { return kind_of(limits::kMaxValence, 3); }
  static int kind_of(int valence, int region) {
    return TriangleTables::is_sector_code(valence) ? valence : valence + (limits::kMaxValence + 1) * region;
  }
  static void kind_parts(int kind, int& valence, int& region) {
    if (TriangleTables::is_sector_code(kind)) valence = kind, region = 0;
    else valence = kind % (limits::kMaxValence + 1), region = kind / (limits::kMaxValence + 1);
  }
  void plan(TessellationLayout& layout, const detail::RangeRunner& run) const override;
  Point edge_node(std::size_t prepared_face, int corner, int t, int n, const Point* prepared) const override;
  std::array<double, 2> edge_node_parameter(std::size_t prepared_face, int corner, int t, int n) const override;
  void points(const TessellationLayout& layout, std::size_t begin, std::size_t end, const Point* prepared,
              std::array<float, 3>* out) const override;
  // The unit normal at each of those points (the descent's derivatives; for
  // sqrt(3) exact, from the tables' derivative stencils, version 6).
  void normals(const TessellationLayout& layout, std::size_t begin, std::size_t end, const Point* prepared,
               std::array<float, 3>* out) const override;
  // Both in one pass: each face's points gathered once, a sample's position
  // and derivative sums in one loop over them.
  void points_and_normals(const TessellationLayout& layout, std::size_t begin, std::size_t end, const Point* prepared,
                          std::array<float, 3>* positions, std::array<float, 3>* normals) const override;

  // Below the public interface (tests, benchmarks):
  const TriangleTables& tables() const { return tables_; }
  const TriangleTopology& topology() const { return topology_; }  // of the prepared mesh
  const TrianglePatch& patch(std::size_t prepared_face) const { return patches_[prepared_face]; }
  bool sqrt3() const { return tables_.refinement() == TriangleRefinement::Sqrt3; }
  // Where an exact parameter of an original face lands: a prepared face and its parameter there.
  std::pair<std::size_t, ExactParameter> locate(std::size_t face, const ExactParameter& at) const;
  // The same for a real parameter.
  std::pair<std::size_t, std::array<double, 2>> locate(std::size_t face, double u, double v) const;

 private:
  template <class P>
  std::pair<std::size_t, std::array<P, 2>> locate_any(std::size_t face, P u, P v) const;
  template <class P>
  Approximation descend(std::size_t face, P u, P v, double tolerance, const Point* prepared) const;
  // The prepared face holding (u, v) of original face `face`, and the parameter in its patch's own coordinates.
  template <class P>
  std::pair<std::size_t, std::array<P, 2>> patch_parameter(std::size_t face, P u, P v) const;
  bool real_stencil(std::size_t face, double u, double v, PatchStencil& out) const override;
  template <class P>
  bool descent_stencil(std::size_t face, P u, P v, PatchStencil& out) const;
  // A stored rate's stencil at the parameter, without descent.
  bool held_stencil(std::size_t face, const ExactParameter& at, PatchStencil& out) const;
  const TrianglePatchDescent& checked_descent() const;
  // The tessellation's samples of prepared faces [begin, end): positions, unit normals or both.
  template <bool kPositions, bool kNormals>
  void samples(const TessellationLayout& layout, std::size_t begin, std::size_t end, const Point* prepared,
               std::array<float, 3>* positions, std::array<float, 3>* normals) const;
  // A sub-patch's control points over its kind's layout (a sector's without its box), and its kind's parts.
  std::vector<Point> layout_points(const SubPatch& in, int& valence, int& region) const;
  // The normal at an extraordinary vertex from the tables' tangent stencils;
  // det: the sign of the face-to-patch map's orientation.
  Point vertex_normal(const TrianglePatch& patch, double det, const Point* prepared) const;
  struct Prepared;
  static Prepared prepare(const Tables& tables, const Connectivity& mesh, const MeshFeatures& sharp);
  // The levels refined round the semi-sharp features left on the prepared mesh (Loop), their patches and tree.
  static void refine_round_features(Prepared& out, const TriangleTables& tables, const LevelSharpness& sharpness,
                                    const CurveCreaseRule& crease, bool boundary_corners, bool no_boundary_surface);
  TriangleFamily(std::shared_ptr<const Tables> tables, Prepared prepared);

  std::shared_ptr<const Tables> holder_;  // keeps tables_ alive
  const TriangleTables& tables_;
  int steps_ = 0;
  int crease_steps_ = 0;  // of the steps, those with sharp rules
  TriangleTopology topology_;
  // By node: the prepared faces first, then the faces of the levels refined
  // round semi-sharp features (family/semi_sharp_levels.hpp), a tree below the
  // prepared faces that have them. A leaf has a patch; an inner node's four
  // children (Loop's split: the corners' children, then the middle one) start
  // one after another (family/feature_tree.hpp). An inner node's patch is the hull of the surface below it.
  std::vector<TrianglePatch> patches_;
  // The sub-patch kind of an inner node of that tree (closest points): split()
  // gives its four children, evaluate() descends to a leaf.
  static constexpr int kRefinedKind = -1;
  FeatureTree tree_;  // empty: no such levels
  int feature_levels_ = 0;
  std::size_t feature_faces_ = 0;
  bool refined(std::size_t node) const { return tree_.refined(node); }
  // Where the point (a, b) / d of a node lands: the leaf and the point there, over the same d.
  std::size_t leaf_of(std::size_t node, long& a, long& b, long d) const;
  // The whole patch of the leaf below an inner node that holds (x, y) (the prepared face's coordinates).
  SubPatch leaf_patch(const SubPatch& node, double x, double y) const;
  // A sub-patch's points from a node's patch (a sector's with its box).
  void node_points(const TrianglePatch& patch, const Point* prepared, std::vector<Point>& out) const;
  std::optional<TrianglePatchDescent> descent_;  // when the tables hold the patch subdivision
  std::optional<FaceDerivativeRows> derivative_rows_;  // where the regular basis is polynomial (Loop): tessellation normals
  mutable std::once_flag affine_once_;
  mutable std::unique_ptr<const AffineParameters> affine_;  // of the regular kind, where the scheme reproduces affine functions
  mutable std::once_flag polynomial_once_;
  mutable std::unique_ptr<const PolynomialPatch> polynomial_;  // of the regular kind, where its basis is polynomial (Loop)
  // The derivative stencils at the n^2 tessellation centres of a patch kind
  // (valence, region) over its m points, made by the descent on first use and
  // kept: centre c (up_centre_index, down_centre_index, in the patch's own
  // coordinates) has m weights of d/du at 2mc, then m of d/dv.
  mutable std::mutex centre_derivatives_mutex_;
  mutable std::map<std::tuple<int, int, int>, std::shared_ptr<const std::vector<double>>> centre_derivatives_;
  std::shared_ptr<const std::vector<double>> centre_derivatives(int valence, int region, int n, std::size_t m) const;
};

// Index of up centre (i, j) and down centre (i, j) among a face's n^2 tessellation
// points: first the n(n+1)/2 up centres ((3i+1)/(3n), (3j+1)/(3n)), i + j <= n-1,
// then the n(n-1)/2 down centres ((3i+2)/(3n), (3j+2)/(3n)), i + j <= n-2, each
// row by row (j-major), in the face's own parameterisation.
inline int up_centre_index(int i, int j, int n) { return j * n - j * (j - 1) / 2 + i; }
inline int down_centre_index(int i, int j, int n) { return n * (n + 1) / 2 + j * (n - 1) - j * (j - 1) / 2 + i; }

}  // namespace stencil_runtime
