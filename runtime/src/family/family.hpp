#pragma once
// What a scheme family (quad or triangle) provides below the public interface:
// the prepared mesh of one control mesh (refinement matrix, which prepared
// faces cover each original face, every prepared face's patch) and the kernels
// that evaluate it. SurfaceTopology, Surface and TessellationPlan call only this.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "face_hierarchy.hpp"
#include "parameter_ops.hpp"
#include "mesh/connectivity.hpp"
#include "range_runner.hpp"
#include "refinement.hpp"
#include "rim_node.hpp"
#include "sub_domain.hpp"
#include "stencil_runtime/derivatives.hpp"
#include "stencil_runtime/exact_parameter.hpp"
#include "stencil_runtime/face_domain.hpp"
#include "stencil_runtime/limits.hpp"

namespace stencil_runtime {

// The weights of one limit point over the control points of a prepared patch.
struct PatchStencil {
  std::size_t face = 0;             // the prepared face
  const int* points = nullptr;      // its patch's prepared vertices
  std::size_t size = 0;
  const double* weights = nullptr;  // `size` weights: into the tables, `storage` or `computed`
  std::array<double, limits::kMaxPatchPoints> storage{};
  std::vector<double> computed;     // weights found by the patch descent (weights_by_linearity)

  PatchStencil() = default;
  // Copies and moves keep `weights` pointing at their own storage.
  PatchStencil(const PatchStencil& o) { *this = o; }
  PatchStencil& operator=(const PatchStencil& o) {
    if (this == &o) return *this;
    face = o.face, points = o.points, size = o.size, storage = o.storage, computed = o.computed;
    weights = o.weights == o.storage.data() ? storage.data() : (o.weights == o.computed.data() && !o.computed.empty() ? computed.data() : o.weights);
    return *this;
  }
};

// A limit point and how far it may be from the exact one (surface.hpp's Evaluation).
struct Approximation {
  Point point{0, 0, 0};
  double bound = 0;
  bool exact = true;
};

// A piece of a prepared face's patch after local subdivision by the scheme's
// own rules: its control points, and the part of the patch's parameter domain
// it covers (sub_domain.hpp; quads: a square of the patch coordinates,
// extraordinary vertex at (0,0); triangles: a triangle of them). Where the
// scheme's weights are non-negative, the limit surface over it lies in the
// convex hull of its points.
struct SubPatch {
  std::size_t face = 0;  // the prepared face
  int kind = 0;          // the family's patch kind (quads: the valence, 4 for regular; triangles: triangle_family.hpp)
  // Below a prepared face refined round semi-sharp features: the tree's node
  // (kind QuadFamily::kRefinedKind, TriangleFamily::kRefinedKind) or the leaf whose patch this is part of,
  // and the prepared positions root() was given, from which an inner node's
  // descendants take their points (a sub-patch does not outlive its search).
  std::size_t node = 0;
  const Point* positions = nullptr;
  std::vector<Point> points;
  SubDomain domain;
};

// Points gathered afresh from `positions` for the sub-patches below a tree
// node (its children's, or a leaf's whole patch), moved into the frame of the
// node's own points: a search may have moved those by an origin near them
// (face_search.cpp keeps deep sub-patches relative to one), and what it reads
// below the node must be in the same frame. `first` is the prepared vertex
// the node's first point was gathered from.
inline void into_frame_of(const SubPatch& node, int first, std::vector<Point>& points) {
  const Point& from = node.positions[first];
  const Point shift{from[0] - node.points[0][0], from[1] - node.points[0][1], from[2] - node.points[0][2]};
  if (shift[0] == 0 && shift[1] == 0 && shift[2] == 0) return;
  for (Point& p : points)
    for (int k = 0; k < 3; ++k) p[k] -= shift[k];
}

// The most children a sub-patch has under one step (sqrt(3)'s composite step splits a triangle in nine).
constexpr int kMaxSubPatchChildren = 9;

// Where the sub-patches of one kind reproduce affine functions of their
// parameter: the parameter g_i of each control point (in the sub-patch's own
// unit frame (square or triangle, `triangle`), in the order of SubPatch::points) with sum_i phi_i(x) g_i = x
// and sum_i phi_i(x) = 1, and the largest deviation from both found when
// checking them on exact evaluations. The closest-point search then bounds a
// sub-patch's surface by its control points' distance from an affine image of
// its domain, a much tighter enclosure than their hull.
struct AffineParameters {
  std::vector<std::array<double, 2>> at;
  bool triangle = false;
  double residual = 0;
};

// Where the sub-patches of one kind are polynomial over their own unit frame
// (the square, or the triangle when `triangle`): the surface is
// sum_i P_i sum_m coefficients[i][m] X^e Y^f with (e, f) = monomials[m], i
// in the order of SubPatch::points; `degree` is the degree per axis (square)
// or the total degree (triangle). The closest-point search bounds such a
// sub-patch's second derivatives by their Bernstein coefficients and so proves
// the squared distance convex over it (distance/convex_bound.hpp).
struct PolynomialPatch {
  bool triangle = false;
  int degree = 0;
  std::vector<std::array<int, 2>> monomials;
  std::vector<std::vector<double>> coefficients;
};

// An original face and a parameter in its domain.
struct FaceParameterReal {
  std::size_t face = 0;
  double u = 0, v = 0;
};

// Points and polygons of a tessellation, planned once: `rates` (one stored
// rate per prepared face) in, point offsets and polygons out.
struct TessellationLayout {
  std::vector<int> rates;
  std::vector<std::size_t> point_offsets;  // size prepared faces + 1
  std::vector<char> holes;                 // per prepared face (no points, no polygons), or empty
  std::vector<RimNode> rim;                // the rim's points, after the faces' (family/seam_polygons.hpp)
  std::vector<std::array<int, 4>> quads;
  std::vector<std::array<int, 3>> triangles;
};

class Family {
 public:
  virtual ~Family() = default;

  const Refinement& refinement() const { return refinement_; }
  // The mesh this family was made from is over vertices gathered from
  // `control` control vertices, vertex v being control vertex origin[v]
  // (mesh/manifold_input.hpp): a first step that copies them.
  void gather_from(std::size_t control, const std::vector<int>& origin) {
    RefinementStep step;
    step.input_vertices = control;
    SparseEntries row;
    for (int o : origin) {
      row.assign(1, {static_cast<std::uint32_t>(o), 1.0});
      step.add_row(row);
    }
    refinement_.prepend(std::move(step));
  }
  const FaceHierarchy& hierarchy() const { return hierarchy_; }
  // The prepared mesh's faces (all quads or all triangles), over the prepared vertices.
  const Connectivity& prepared() const { return prepared_; }
  // The steps applied, for messages: e.g. "1 subdivision step".
  virtual std::string preparation() const = 0;
  virtual int refinement_steps() const = 0;
  // Whether the mesh has boundary edges (a quad family's meshes may).
  virtual bool has_boundary() const { return false; }
  // Whether vertex v (of the control mesh: the steps keep its number) is on the boundary.
  virtual bool on_boundary(int /*vertex*/) const { return false; }
  // What (u, v) means on original face `face`.
  virtual FaceDomain domain(std::size_t face) const = 0;

  // The weights at an exact parameter (inside domain(face)) of an original
  // face, over prepared vertices: from a stored rate that holds it, or from the
  // patch descent where that is exact (it reaches a stored rate's grid, or a
  // regular patch whose basis is polynomial); false otherwise.
  virtual bool stencil(std::size_t face, const ExactParameter& at, PatchStencil& out) const = 0;
  // The same at a real parameter (a double is an exact binary fraction).
  bool stencil(std::size_t face, double u, double v, PatchStencil& out) const {
    const auto fu = exact_fraction(u), fv = exact_fraction(v);
    if (fu && fv) return stencil(face, ExactParameter{*fu, *fv}, out);
    return real_stencil(face, u, v, out);
  }

  // The limit point at any parameter (inside domain(face)) from the prepared
  // positions: exact where the tables hold the parameter, directly or after
  // the scheme's own subdivision of the patch; otherwise within `tolerance`
  // (absolute, > 0), with the bound reported. Throws EvaluationError where the
  // scheme's tables give no rigorous bound.
  virtual Approximation evaluate(std::size_t face, const ExactParameter& at, double tolerance, const Point* prepared) const = 0;
  virtual Approximation evaluate(std::size_t face, double u, double v, double tolerance, const Point* prepared) const = 0;

  // The limit point and its derivatives along the original face's (u, v), from
  // the prepared positions, wherever the family computes them exactly (quads:
  // quad_family.hpp); throws EvaluationError elsewhere. The default: a family
  // without derivatives yet.
  virtual Derivatives derivatives(std::size_t face, const ExactParameter& at, const Point* prepared) const;
  virtual Derivatives derivatives(std::size_t face, double u, double v, const Point* prepared) const;
  // With second derivatives, where the family has them exactly (quads with
  // polynomial regular patches); throws EvaluationError elsewhere.
  // The unit normal: from the derivatives where they exist, and at an
  // extraordinary vertex from the tables' tangent stencils (families that
  // have them), so that a normal exists everywhere on a C1 surface.
  virtual Point normal(std::size_t face, const ExactParameter& at, const Point* prepared) const {
    return derivatives(face, at, prepared).normal();
  }
  virtual Point normal(std::size_t face, double u, double v, const Point* prepared) const {
    return derivatives(face, u, v, prepared).normal();
  }
  virtual SecondDerivatives second_derivatives(std::size_t face, const ExactParameter& at, const Point* prepared) const;
  virtual SecondDerivatives second_derivatives(std::size_t face, double u, double v, const Point* prepared) const;

  // Sub-patches (closest points, fitting): the whole patch of a prepared face,
  // its children under one step of the scheme, the limit point at a patch
  // parameter inside a sub-patch, and which original face and parameter a
  // prepared face's patch parameter is. Whether the control points of every
  // sub-patch bound its surface (all subdivision weights non-negative); tables
  // without patch subdivision data throw EvaluationError here.
  virtual bool hull_bounds() const = 0;
  virtual void root(std::size_t prepared_face, const Point* prepared, SubPatch& out) const = 0;
  virtual int split(const SubPatch& in, SubPatch* children) const = 0;  // at most kMaxSubPatchChildren
  virtual Approximation evaluate(const SubPatch& in, double x, double y, double tolerance) const = 0;
  virtual FaceParameterReal original(std::size_t prepared_face, double x, double y) const = 0;
  // The limit point and its derivatives in the patch parameters at, or next
  // to, (x, y) inside a sub-patch, exactly: where the scheme's derivatives
  // are exact only on stored grids, (x, y) moves to the nearest point of the
  // sub-patch's finest stored grid. False where there is none (an
  // extraordinary vertex, tables without derivatives, a family without them).
  virtual bool derivatives(const SubPatch& /*in*/, double& /*x*/, double& /*y*/, Derivatives& /*out*/) const { return false; }
  // The point at (x, y) of a sub-patch: exact, with derivatives(), where the
  // family has them there (perhaps at a grid point next to (x, y), where
  // (x, y) then moves: far cheaper than a bounded evaluation between the
  // grids, sqrt(3)); else evaluate() within `tolerance`.
  Approximation nearby_point(const SubPatch& in, double& x, double& y, double tolerance) const {
    Derivatives d;
    double gx = x, gy = y;
    if (derivatives(in, gx, gy, d)) {
      x = gx, y = gy;
      return {d.point, 0, true};
    }
    return evaluate(in, x, y, tolerance);
  }
  // Sub-patches of kind `kind` that reproduce affine functions (null: none
  // known), and the largest kind number the family uses.
  virtual const AffineParameters* affine_parameters(int /*kind*/) const { return nullptr; }
  // Sub-patches of kind `kind` whose surface is polynomial over their unit frame (null: not known to be).
  virtual const PolynomialPatch* polynomial_patch(int /*kind*/) const { return nullptr; }
  virtual int max_kind() const = 0;

  // The unit normals at the points of prepared faces [begin, end) of a planned
  // layout (where points() puts the positions). The default: a family without
  // derivatives yet.
  virtual void normals(const TessellationLayout& layout, std::size_t begin, std::size_t end, const Point* prepared,
                       std::array<float, 3>* out) const;
  // points() and normals() of the same faces; the default runs one after the
  // other over the range (its points still in cache), a family may fuse them.
  virtual void points_and_normals(const TessellationLayout& layout, std::size_t begin, std::size_t end,
                                  const Point* prepared, std::array<float, 3>* positions,
                                  std::array<float, 3>* normals) const {
    points(layout, begin, end, prepared, positions);
    this->normals(layout, begin, end, prepared, normals);
  }

  // Fills layout.point_offsets, quads and triangles for layout.rates.
  virtual void plan(TessellationLayout& layout, const detail::RangeRunner& run) const = 0;
  // The points of prepared faces [begin, end) of a planned layout, from the
  // prepared positions, into out[layout.point_offsets[f]...].
  virtual void points(const TessellationLayout& layout, std::size_t begin, std::size_t end, const Point* prepared,
                      std::array<float, 3>* out) const = 0;
  // The limit point at grid node t (0..n) of the edge from corner k of a
  // prepared face at rate n (a rim point), and the same node in the patch
  // coordinates that original() takes.
  virtual Point edge_node(std::size_t prepared_face, int corner, int t, int n, const Point* prepared) const = 0;
  virtual std::array<double, 2> edge_node_parameter(std::size_t prepared_face, int corner, int t, int n) const = 0;

 protected:
  // stencil() at a double that is no fraction of 64-bit integers: the descent in doubles.
  virtual bool real_stencil(std::size_t face, double u, double v, PatchStencil& out) const = 0;

  Refinement refinement_;
  FaceHierarchy hierarchy_;
  Connectivity prepared_;
};

// The weights of a patch evaluation that is linear in the patch's `count`
// control points and exact: its images of unit vectors, three points at a time
// (one per coordinate). `evaluate(points)` consumes the points and returns an
// Approximation; false when one is not exact (the descent then stopped on a
// bound that depends on the positions, and no row over the points exists).
template <class Evaluate>
bool weights_by_linearity(std::size_t count, const Evaluate& evaluate, std::vector<double>& weights) {
  weights.assign(count, 0.0);
  std::vector<Point> unit;
  for (std::size_t first = 0; first < count; first += 3) {
    unit.assign(count, Point{0, 0, 0});
    for (std::size_t k = 0; k < 3 && first + k < count; ++k) unit[first + k][k] = 1;
    const Approximation a = evaluate(unit);
    if (!a.exact) return false;
    for (std::size_t k = 0; k < 3 && first + k < count; ++k) weights[first + k] = a.point[k];
  }
  return true;
}

// The same for the first derivatives: `differentiate(points)` consumes the
// points and returns their Derivatives; out gets the count weights of du, then
// the count weights of dv.
template <class Differentiate>
void derivative_weights_by_linearity(std::size_t count, const Differentiate& differentiate, double* out) {
  std::vector<Point> unit;
  for (std::size_t first = 0; first < count; first += 3) {
    unit.assign(count, Point{0, 0, 0});
    for (std::size_t k = 0; k < 3 && first + k < count; ++k) unit[first + k][k] = 1;
    const Derivatives d = differentiate(unit);
    for (std::size_t k = 0; k < 3 && first + k < count; ++k) out[first + k] = d.du[k], out[count + first + k] = d.dv[k];
  }
}

// The stencil of prepared face `face` whose patch has the control points
// `points`, by linearity from `evaluate` (above); false when it is not exact.
template <class Evaluate>
bool linear_stencil(std::size_t face, const std::vector<int>& points, const Evaluate& evaluate, PatchStencil& out) {
  if (!weights_by_linearity(points.size(), evaluate, out.computed)) return false;
  out.face = face;
  out.points = points.data();
  out.size = points.size();
  out.weights = out.computed.data();
  return true;
}

// The valence check every family makes before preparing, with messages that
// say what to do: valences below 3 and above limits::kMaxValence are refused as
// such; the valences the tables lack are all named, with the stencilgen call
// that writes tables covering them together with every valence and rate the
// tables already hold.
class ValenceCheck {
 public:
  // `regular`: the valence whose patch is the regular one (4 or 6), which
  // stencilgen always writes.
  ValenceCheck(std::vector<int> table_valences, std::vector<int> table_rates, std::string scheme, int regular)
      : table_valences_(std::move(table_valences)), table_rates_(std::move(table_rates)), scheme_(std::move(scheme)),
        regular_(regular) {}
  // One vertex; `who` (e.g. "vertex 12") is used only in a message.
  void add(int valence, const std::string& who);
  template <class Who>
  void add_lazy(int valence, const Who& who) {
    if (valence < 3 || valence > limits::kMaxValence || !covered(valence)) add(valence, who());
  }
  // A vertex on the boundary in `faces` faces whose sector the tables lack:
  // tables with valences up to max(faces, 3) cover it. `who` describes it whole.
  void add_boundary(int faces, const std::string& who);
  // Throws MeshError when some valence is missing.
  void finish() const;

 private:
  bool covered(int valence) const;
  std::vector<int> table_valences_, table_rates_;
  std::string scheme_;
  int regular_;
  std::vector<int> missing_;
  std::string first_missing_;
};

// "3-8,10" from a sorted list; a list of one value v is written "v-v" when
// `always_range` (stencilgen's --n reads a lone N as 1..N).
std::string compact_list(const std::vector<int>& sorted, bool always_range);

}  // namespace stencil_runtime
