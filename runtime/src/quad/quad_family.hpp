#pragma once
// A closed mesh under a quad scheme's tables, prepared (docs/runtime.md): the
// scheme's polygon step where the mesh has other polygons, then whole-mesh
// steps of the scheme's own rules until no face has two extraordinary corners,
// and every prepared face's patch gathered; exact evaluation from the tables
// and the tessellation kernels (quad_tessellation.cpp).
#include <map>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "family/crease_step.hpp"
#include "family/family.hpp"
#include "family/feature_tree.hpp"
#include "mesh/connectivity.hpp"
#include "mesh/uniform_topology.hpp"
#include "patch_descent.hpp"
#include "quad_patch.hpp"
#include "stencil_runtime/tables.hpp"
#include "tables/quad_tables.hpp"

namespace stencil_runtime {

class QuadFamily final : public Family {
 public:
  // Throws MeshError naming the face, edge or vertex (see SurfaceTopology::create).
  // `sharp`: semi-sharp creases and corners, resolved by whole-mesh steps with
  // OpenSubdiv's creasing rules (crease_refinement.hpp) before the patches are gathered.
  QuadFamily(std::shared_ptr<const Tables> tables, const Connectivity& mesh, const MeshFeatures& sharp = {});

  std::string preparation() const override;
  int refinement_steps() const override { return steps_ + (polygon_step_ ? 1 : 0); }
  bool has_boundary() const override { return topology_.has_boundary(); }
  bool on_boundary(int vertex) const override { return topology_.on_boundary(vertex); }
  FaceDomain domain(std::size_t face) const override;
  bool stencil(std::size_t face, const ExactParameter& at, PatchStencil& out) const override;
  using Family::stencil;  // and at a real parameter
  Approximation evaluate(std::size_t face, const ExactParameter& at, double tolerance, const Point* prepared) const override;
  Approximation evaluate(std::size_t face, double u, double v, double tolerance, const Point* prepared) const override;
  Derivatives derivatives(std::size_t face, const ExactParameter& at, const Point* prepared) const override;
  Derivatives derivatives(std::size_t face, double u, double v, const Point* prepared) const override;
  Point normal(std::size_t face, const ExactParameter& at, const Point* prepared) const override;
  Point normal(std::size_t face, double u, double v, const Point* prepared) const override;
  SecondDerivatives second_derivatives(std::size_t face, const ExactParameter& at, const Point* prepared) const override;
  SecondDerivatives second_derivatives(std::size_t face, double u, double v, const Point* prepared) const override;
  bool hull_bounds() const override;
  void root(std::size_t prepared_face, const Point* prepared, SubPatch& out) const override;
  int split(const SubPatch& in, SubPatch* children) const override;
  Approximation evaluate(const SubPatch& in, double x, double y, double tolerance) const override;
  const AffineParameters* affine_parameters(int kind) const override;
  const PolynomialPatch* polynomial_patch(int kind) const override;
  int max_kind() const override { return limits::kMaxValence; }
  bool derivatives(const SubPatch& in, double& x, double& y, Derivatives& out) const override;
  FaceParameterReal original(std::size_t prepared_face, double x, double y) const override;
  void plan(TessellationLayout& layout, const detail::RangeRunner& run) const override;
  Point edge_node(std::size_t prepared_face, int corner, int t, int n, const Point* prepared) const override;
  std::array<double, 2> edge_node_parameter(std::size_t prepared_face, int corner, int t, int n) const override;
  void points(const TessellationLayout& layout, std::size_t begin, std::size_t end, const Point* prepared,
              std::array<float, 3>* out) const override;
  void normals(const TessellationLayout& layout, std::size_t begin, std::size_t end, const Point* prepared,
               std::array<float, 3>* out) const override;
  void points_and_normals(const TessellationLayout& layout, std::size_t begin, std::size_t end, const Point* prepared,
                          std::array<float, 3>* positions, std::array<float, 3>* normals) const override;

  // Below the public interface (tests, benchmarks):
  const QuadTables& tables() const { return tables_; }
  const QuadTopology& topology() const { return topology_; }  // of the prepared mesh
  const QuadPatch& patch(std::size_t prepared_face) const { return patches_[prepared_face]; }
  // Where an exact parameter of an original face lands: a prepared face and its parameter there.
  std::pair<std::size_t, ExactParameter> locate(std::size_t face, const ExactParameter& at) const;
  // The same for a real parameter (u, v): the prepared face and its (u, v) there.
  std::pair<std::size_t, std::array<double, 2>> locate(std::size_t face, double u, double v) const;

 private:
  struct Prepared;
  static Prepared prepare(const Tables& tables, const Connectivity& mesh, const MeshFeatures& sharp);
  // The levels refined round the semi-sharp features left on the prepared mesh, their patches and tree.
  static void refine_round_features(Prepared& out, const QuadTables& tables, const LevelSharpness& sharpness,
                                    const CurveCreaseRule& crease, bool edge_and_corner);
  QuadFamily(std::shared_ptr<const Tables> tables, Prepared prepared);

  std::shared_ptr<const Tables> holder_;  // keeps tables_ alive
  const QuadTables& tables_;
  std::vector<int> original_sizes_;
  bool polygon_step_ = false;
  int crease_steps_ = 0;  // steps (the polygon step included) with sharp rules
  int steps_ = 0;  // isolation steps (after the polygon step)
  QuadTopology topology_;
  // By node: the prepared faces first, then the faces of the levels refined
  // round semi-sharp features (semi_sharp_levels.hpp), a tree below the
  // prepared faces that have them. A leaf has a patch; an inner node's four
  // children (its quadrants, as in subdivide_quads) follow each other (family/feature_tree.hpp).
  std::vector<QuadPatch> patches_;
  // The sub-patch kind of an inner node of that tree (closest points): its
  // points are the node's 1-ring at its level, whose hull holds the surface
  // below it; split() gives its four children, evaluate() descends to a leaf.
  static constexpr int kRefinedKind = -1;
  // A node's own coordinates as seen through `parent`'s domain: the quadrant c's map, then a patch's rotation.
  static SubDomain child_domain(const SubDomain& parent, int c, int rotation);
  // The whole patch of the leaf below an inner node that holds (x, y) (the prepared face's patch coordinates).
  SubPatch leaf_patch(const SubPatch& node, double x, double y) const;
  FeatureTree tree_;  // empty: no such levels
  int feature_levels_ = 0;
  std::size_t feature_faces_ = 0;
  bool refined(std::size_t node) const { return tree_.refined(node); }
  // Where the point (a, b) / d of a refined node's square lands: the leaf and the point there, over the same d.
  std::size_t leaf_of(std::size_t node, long& a, long& b, long d) const;
  // The limit point at (a, b) / (2n) of a prepared face refined round features, from its leaves' stencils at rate n.
  Point refined_point(std::size_t face, long a, long b, int n, const Point* prepared) const;
  // Its unit normal there where the leaf is regular (the tensor product of the curve and its
  // derivative at the node, when the tables hold it); false elsewhere.
  bool refined_regular_normal(std::size_t face, long a, long b, int n, const Point* prepared, Point& normal) const;
  // A prepared face's (or a tree node's) own coordinates (u, v) to its original face's.
  FaceParameterReal original_of_face(std::size_t node, double u, double v) const;
  // Per stored rate n (indexed by n): phi at the n cell centres, 4 weights each.
  std::vector<std::vector<double>> centre_weights_;
  // The same for phi' (empty when the tables hold no phi').
  std::vector<std::vector<double>> centre_derivative_weights_;
  std::unique_ptr<const QuadPatchDescent> descent_;  // null for tables without the patch subdivision
  // d/dx and d/dy weights of an extraordinary patch at its n^2 cell centres in
  // patch coordinates, per (valence, rate): made on first use by the descent
  // (by linearity) and kept, so that tessellation normals do not descend per point.
  mutable std::mutex centre_derivatives_mutex_;
  mutable std::map<std::pair<int, int>, std::shared_ptr<const std::vector<double>>> centre_derivatives_;
  std::shared_ptr<const std::vector<double>> centre_derivatives(int valence, int n) const;

  // The regular patch's control-point parameters, found once on first use.
  mutable std::once_flag affine_once_;
  mutable std::unique_ptr<const AffineParameters> affine_;
  mutable std::once_flag polynomial_once_;
  mutable std::unique_ptr<const PolynomialPatch> polynomial_;

  const QuadPatchDescent& checked_descent() const;  // throws EvaluationError without descent data
  // d(patch x, y)/d(u, v), row-major: the product of every step's linear part
  // (2 per level, and the quadrant's or the patch's rotation).
  using Jacobian = std::array<double, 4>;
  template <class P>
  std::pair<std::size_t, std::array<P, 2>> locate_any(std::size_t face, P u, P v, Jacobian* jacobian = nullptr) const;
  // The control points of the patch holding (u, v) of original face `face`,
  // its valence and the parameter there, and the Jacobian to the face's (u, v).
  template <class P>
  std::pair<int, std::array<P, 2>> patch_points(std::size_t face, P u, P v, const Point* prepared, Jacobian& j,
                                                std::vector<Point>& points) const;
  template <class P>
  Derivatives derivatives_any(std::size_t face, P u, P v, const Point* prepared) const;
  template <class P>
  Point normal_any(std::size_t face, P u, P v, const Point* prepared) const;
  template <class P>
  SecondDerivatives second_derivatives_any(std::size_t face, P u, P v, const Point* prepared) const;
  template <class P>
  Approximation descend(std::size_t face, P u, P v, double tolerance, const Point* prepared) const;
  // The prepared face holding (u, v) of original face `face`, and the parameter in its patch's own coordinates.
  template <class P>
  std::pair<std::size_t, std::array<P, 2>> patch_parameter(std::size_t face, P u, P v, Jacobian* jacobian = nullptr) const;
  bool real_stencil(std::size_t face, double u, double v, PatchStencil& out) const override;
  template <class P>
  bool descent_stencil(std::size_t face, P u, P v, PatchStencil& out) const;
};

}  // namespace stencil_runtime
