#include "quad_family.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "family/parameter_ops.hpp"
#include "family/stencil_sum.hpp"
#include "mesh/polygon_links.hpp"
#include "quad_creases.hpp"
#include "family/local_region.hpp"
#include "family/sharp_cut.hpp"
#include "quad_refinement.hpp"
#include "regular_face_samples.hpp"
#include "semi_sharp_levels.hpp"

namespace stencil_runtime {

struct QuadFamily::Prepared {
  Refinement refinement;
  FaceHierarchy hierarchy;
  std::vector<int> original_sizes;
  bool polygon_step = false;
  int crease_steps = 0;  // of the steps, those that still had sharp features
  int steps = 0;
  Connectivity mesh;  // the prepared mesh
  bool boundary = false;
  bool no_boundary_surface = false;  // `none`: faces at boundary vertices have no surface (holes), hence no patch
  std::vector<QuadPatch> patches;  // by node (quad_family.hpp): the prepared faces', then the feature levels'
  FeatureTree tree;
  int feature_levels = 0;
  std::size_t feature_faces = 0;
};

namespace {

// The corner of face f at a boundary vertex with a sector patch (sector_vertex), or -1.
int sector_corner(const QuadTopology& topo, std::size_t f, const std::vector<SectorRule>& corner) {
  for (int c = 0; c < 4; ++c)
    if (sector_vertex(topo, topo.vertex(f, c), corner)) return c;
  return -1;
}

// Whether every face has a patch: at most one extraordinary corner; a face at
// a boundary vertex in other than two faces (or a corner) its sector's patch;
// any other face touching the boundary one of the regular boundary patches
// (with `none`, faces touching the mesh's own boundary have no surface, hence
// no patch). `topo` is the mesh cut along its infinitely sharp edges
// (sharp_cut.hpp), whose boundaries are the mesh's and its creases, `corner`
// its vertices' rules, `no_surface` per vertex whether the faces at it have no
// surface (empty: none). face_ready: the same for one face, but the slits
// (checked per vertex).
bool face_ready(const QuadTopology& topo, std::size_t f, const std::vector<SectorRule>& corner, const std::vector<char>& no_surface) {
  if (topo.touches_boundary(f)) {
    if (topo.touches_marked(f, no_surface)) return true;
    const int c = sector_corner(topo, f, corner);
    return c >= 0 ? sector_patch_ready(topo, f, c, corner) : boundary_patch_ready(topo, f, corner);
  }
  int extraordinary = 0;
  for (int c = 0; c < 4; ++c) extraordinary += !regular_inside(topo, topo.vertex(f, c), corner);
  return extraordinary <= 1;
}

bool isolated(const QuadTopology& topo, const std::vector<SectorRule>& corner, const std::vector<char>& no_surface) {
  for (std::size_t v = 0; v < topo.vertices(); ++v)
    if (slit_end_inside(corner[v], topo.on_boundary(static_cast<int>(v)))) return false;
  for (std::size_t f = 0; f < topo.faces(); ++f)
    if (!face_ready(topo, f, corner, no_surface)) return false;
  return true;
}

using PhantomRows = std::vector<std::vector<std::pair<int, double>>>;

// The patch of a face that is ready (face_ready) on the cut topology; a face
// without surface (`none`) gets a placeholder, never evaluated.
QuadPatch face_patch(const QuadTopology& topo, std::size_t f, const std::vector<SectorRule>& rule,
                     const std::vector<char>& no_surface, std::size_t first_phantom, PhantomRows& phantoms) {
  if (!topo.touches_boundary(f)) return gather_quad_patch(topo, f, rule);
  QuadPatch p;
  const int c = sector_corner(topo, f, rule);
  if (topo.touches_marked(f, no_surface)) p.points.assign(16, 0);
  else if (c >= 0) p = gather_sector_patch(topo, f, c, rule);
  else p = gather_boundary_patch(topo, f, first_phantom, phantoms);
  return p;
}

// The vertices of the input mesh, cut along its infinitely sharp edges: inside
// ones need their valence in the tables; those on a boundary or crease in
// other than two faces (or a corner in more than one) their sector's patches
// (steps keep a vertex's number of faces, so this is checked once on the
// input). stencilgen writes sectors for up to as many faces as the largest
// valence it is given.
void check_vertices(const SharpCut& cut, const PolygonLinks& links, const std::vector<char>& no_surface,
                    const QuadTables& tables, ValenceCheck& valences) {
  for (std::size_t v = 0; v < cut.mesh.vertex_count; ++v) {
    const int k = links.valence[v];
    const std::string who = "vertex " + std::to_string(cut.origin[v]);
    if (!links.boundary[v] && !ends_slit(cut.rule[v])) {
      if (cut.rule[v] != SectorRule::Cone) {
        valences.add_lazy(k, [&] { return who; });
      } else if (!tables.has_sector({SectorRule::Cone, k, 0})) {
        const std::string what = who + " is a cone point (infinitely sharp, on no infinitely sharp edge) of valence " + std::to_string(k);
        if (!tables.has_sector_rule(SectorRule::Cone))  // none at all: tables from before cone points
          throw MeshError(what + "; these tables hold no patches for cone points (descent.json before version 4): "
                                 "regenerate them with this stencilgen");
        valences.add_boundary(k, what + " (tables cover those up to their largest valence)");
      }
      continue;
    }
    if (!no_surface.empty() && no_surface[v]) continue;  // no surface there: any will do
    const SectorRule rule = cut.rule[v];
    if ((k == 2 && rule == SectorRule::Crease) || (k == 1 && rule == SectorRule::Corner)) continue;  // regular boundary patches
    if (k > limits::kMaxValence)
      throw MeshError(who + " is on a boundary or crease in " + std::to_string(k) + " faces; the runtime supports up to " +
                      std::to_string(limits::kMaxValence));
    if (!tables.has_sector({rule, k, 0}))
      valences.add_boundary(k, who + (rule == SectorRule::Dart ? " ends an infinitely sharp crease (a dart) at valence " + std::to_string(k)
                                                               : std::string(" is ") + (rule == SectorRule::Corner ? "a corner" : "on a boundary or crease") +
                                                                     " in " + std::to_string(k) + " face" + (k == 1 ? "" : "s")) +
                                   " (tables cover those in up to as many faces as their largest valence)");
  }
}



// Child c of a face split into quadrants (subdivide_quads) and the parameter
// there: c is the quadrant of (u, v), the child's u axis along the parent's
// edge c -> c+1. P is Fraction or double.
template <class P>
std::pair<int, std::array<P, 2>> quadrant(const P& u, const P& v) {
  const bool right = greater(u, 1, 2), top = greater(v, 1, 2);
  const P x = scale_minus(u, 2, right ? 1 : 0), y = scale_minus(v, 2, top ? 1 : 0);
  const int c = !top ? (right ? 1 : 0) : (right ? 2 : 3);
  switch (c) {
    case 0: return {0, {x, y}};
    case 1: return {1, {y, from(1, x)}};
    case 2: return {2, {from(1, x), from(1, y)}};
    default: return {3, {from(1, y), x}};
  }
}

// A quadrant child's (u, v) to its parent's: the inverse of quadrant().
void to_parent(int c, double& u, double& v) {
  double pu = 0, pv = 0;
  switch (c) {
    case 0: pu = u / 2, pv = v / 2; break;
    case 1: pu = (2 - v) / 2, pv = u / 2; break;
    case 2: pu = (2 - u) / 2, pv = (2 - v) / 2; break;
    default: pu = v / 2, pv = (2 - u) / 2; break;
  }
  u = pu, v = pv;
}

// A sub-face of an N-gon's domain and its own coordinates.
int subface(const FaceDomain& d, const Fraction& u, const Fraction& v, std::array<Fraction, 2>& local) {
  ExactParameter l;
  const int s = d.subface({u, v}, l);
  local = {l.u, l.v};
  return s;
}
int subface(const FaceDomain& d, double u, double v, std::array<double, 2>& local) { return d.subface(u, v, local[0], local[1]); }

}  // namespace

QuadFamily::Prepared QuadFamily::prepare(const Tables& tables, const Connectivity& mesh, const MeshFeatures& features) {
  const QuadTables& t = tables.quad();
  QuadFamily::Prepared out;
  out.refinement = Refinement(mesh.vertex_count);
  out.hierarchy.original_faces = mesh.face_count();
  out.original_sizes = mesh.face_sizes;
  const PolygonLinks links = link_polygons(mesh, true);  // a manifold (names the face, edge or vertex)
  const bool edge_and_corner = features.boundary == BoundaryInterpolation::EdgeAndCorner;
  out.boundary = links.has_boundary;
  out.no_boundary_surface = links.has_boundary && features.boundary == BoundaryInterpolation::None;
  LevelSharpness sharpness = LevelSharpness::of(mesh, features, true);
  BoundaryRules boundary;
  ValenceCheck valences(tables.valences(), t.rates(), tables.scheme(), 4);
  {
    const SharpCut input = cut_along_sharp_edges(mesh, links, sharpness, edge_and_corner);
    check_vertices(input, input.cut ? link_polygons(input.mesh, true) : links,
                   no_surface_vertices(out.no_boundary_surface, mesh, links, sharpness, input), t, valences);
  }
  if (links.has_boundary) {
    const CurveCreaseRule crease = quad_crease_rule(t, tables.scheme());
    boundary = {crease.centre, crease.neighbour, edge_and_corner};
  }
  const BoundaryRules* rules = links.has_boundary ? &boundary : nullptr;
  const bool all_quads = std::all_of(mesh.face_sizes.begin(), mesh.face_sizes.end(), [](int k) { return k == 4; });
  if (!all_quads) {
    if (!t.has_polygon_rules()) {
      const auto it = std::find_if(mesh.face_sizes.begin(), mesh.face_sizes.end(), [](int k) { return k != 4; });
      throw MeshError("face " + std::to_string(it - mesh.face_sizes.begin()) + " has " + std::to_string(*it) +
                      " vertices; this scheme's tables have no rules for polygons other than quads");
    }
    // Each face's centre becomes a vertex whose valence is the face size.
    for (std::size_t f = 0; f < mesh.face_count(); ++f)
      if (mesh.face_sizes[f] != 4)
        valences.add_lazy(mesh.face_sizes[f], [&] {
          return "face " + std::to_string(f) + " (" + std::to_string(mesh.face_sizes[f]) +
                 " vertices, so its centre becomes a vertex of that valence)";
        });
  }
  valences.finish();
  CurveCreaseRule crease;
  // Semi-sharp features by whole-mesh steps where they fit the budget, else
  // refined round them after the isolation (refine_round_features).
  bool local = false;
  if (!sharpness.smooth()) {
    crease = quad_crease_rule(t, tables.scheme());
    const std::size_t first = all_quads ? 4 * mesh.face_count() : mesh.face_vertices.size();
    local = prefer_round_features(mesh, sharpness, first);
    if (!local) check_crease_steps(mesh.face_count(), first, sharpness.max());
  }
  if (all_quads) {
    out.mesh = mesh;
  } else {
    const bool triangles = std::find(mesh.face_sizes.begin(), mesh.face_sizes.end(), 3) != mesh.face_sizes.end();
    if (features.smooth_triangles && triangles) t.check_smooth_triangles();
    QuadStep step = subdivide_polygons(mesh, links, t, features.smooth_triangles, rules);
    if (!sharpness.smooth()) {
      sharpness = sharpen_step(mesh, sharpness, crease, quad_step_edge_points(mesh, step.mesh), step.step, edge_and_corner);
      ++out.crease_steps;
    }
    std::vector<std::size_t> offsets(mesh.face_count() + 1, 0);
    for (std::size_t f = 0; f < mesh.face_count(); ++f) offsets[f + 1] = offsets[f] + static_cast<std::size_t>(mesh.face_sizes[f]);
    out.hierarchy.add(std::move(offsets), 2);
    out.refinement.add(std::move(step.step));
    out.mesh = std::move(step.mesh);
    out.polygon_step = true;
  }
  QuadTopology topo = all_quads ? QuadTopology(out.mesh, links) : QuadTopology(out.mesh, out.boundary);
  // One whole-mesh step of the scheme's rules, with OpenSubdiv's creasing where there are sharp features.
  auto step_once = [&] {
    QuadStep step = subdivide_quads(topo, t, rules);
    if (!sharpness.smooth()) {
      sharpness = sharpen_step(out.mesh, sharpness, crease, quad_step_edge_points(out.mesh, step.mesh), step.step, edge_and_corner);
      ++out.crease_steps;
    }
    out.hierarchy.add_uniform(4, 2);
    out.refinement.add(std::move(step.step));
    out.mesh = std::move(step.mesh);
    ++out.steps;
    topo = QuadTopology(out.mesh, out.boundary);
  };
  // Semi-sharp features decay by at least 1 a step: whole-mesh steps until none
  // is left, after which every patch is stationary again (infinitely sharp
  // ones are boundaries of the cut mesh: sharp_cut.hpp).
  if (!local)
    while (sharpness.has_semi_sharp()) step_once();
  const int before_isolation = out.steps;
  // The whole-mesh step's topology cut along the infinitely sharp edges (the
  // mesh itself where there are none), with its corners and, under `none`,
  // the vertices whose faces have no surface.
  SharpCut cut;
  std::vector<char> no_surface;
  auto cut_level = [&] {
    const PolygonLinks level = link_polygons(out.mesh, true);
    cut = cut_along_sharp_edges(out.mesh, level, sharpness, edge_and_corner);
    no_surface = no_surface_vertices(out.no_boundary_surface, out.mesh, level, sharpness, cut);
    return QuadTopology(cut.mesh, true);
  };
  QuadTopology patch_topo = cut_level();
  while (!isolated(patch_topo, cut.rule, no_surface)) {
    if (out.steps - before_isolation + (out.polygon_step ? 1 : 0) == limits::kMaxRefinementSteps)
      throw MeshError("extraordinary vertices still share faces after " + std::to_string(limits::kMaxRefinementSteps) +
                      " subdivision steps");
    step_once();
    patch_topo = cut_level();
  }
  // The patches, on the cut mesh. Its extra vertices (copies of those on
  // creases) and the points beyond its boundaries (boundary_patch_ready)
  // become prepared points of their own, by steps that keep every vertex and
  // append them.
  if (cut.cut) out.refinement.add(append_rows(out.mesh.vertex_count, copy_rows(cut, out.mesh.vertex_count)));
  PhantomRows phantoms;
  out.patches.resize(patch_topo.faces());
  for (std::size_t f = 0; f < patch_topo.faces(); ++f)
    out.patches[f] = face_patch(patch_topo, f, cut.rule, no_surface, cut.mesh.vertex_count, phantoms);
  if (!phantoms.empty()) out.refinement.add(append_rows(cut.mesh.vertex_count, phantoms));
  if (local) refine_round_features(out, t, sharpness, crease, edge_and_corner);
  return out;
}

void QuadFamily::refine_round_features(Prepared& out, const QuadTables& t, const LevelSharpness& sharpness,
                                       const CurveCreaseRule& crease, bool edge_and_corner) {
  if (!sharpness.has_semi_sharp()) return;  // the isolation steps took it all
  // The boundary rules are the crease curve's, on the mesh's boundaries and on the regions' borders alike.
  SemiSharpRefinement r =
      refine_round_semi_sharp(out.mesh, sharpness, t, crease, {crease.centre, crease.neighbour, edge_and_corner}, edge_and_corner);
  out.feature_levels = static_cast<int>(r.levels.size());
  out.feature_faces = r.faces() - out.mesh.face_count();
  const auto gather = [&](const SharpCut& cut, const std::vector<char>& no_surface, const std::vector<char>& exact,
                          std::vector<QuadPatch>& patches) {
    const QuadTopology topo(cut.mesh, true);
    PhantomRows phantoms;
    for (std::size_t f = 0; f < patches.size(); ++f) {
      if (!exact[f]) continue;
      bool ready = face_ready(topo, f, cut.rule, no_surface);
      for (int c = 0; c < 4; ++c) {
        const int v = topo.vertex(f, c);
        ready = ready && !slit_end_inside(cut.rule[static_cast<std::size_t>(v)], topo.on_boundary(v));
      }
      // Children of isolated faces are isolated: a node without its patch is a mistake here.
      if (!ready) throw MeshError("internal: a face refined round a semi-sharp feature has no patch");
      patches[f] = face_patch(topo, f, cut.rule, no_surface, cut.mesh.vertex_count, phantoms);
    }
    return phantoms;
  };
  hang_levels(r, edge_and_corner, out.no_boundary_surface, out.refinement, out.tree, out.patches, gather);
}

QuadFamily::QuadFamily(std::shared_ptr<const Tables> tables, const Connectivity& mesh, const MeshFeatures& sharp)
    : QuadFamily(tables, prepare(*tables, mesh, sharp)) {}

QuadFamily::QuadFamily(std::shared_ptr<const Tables> tables, Prepared prepared)
    : holder_(std::move(tables)),
      tables_(holder_->quad()),
      original_sizes_(std::move(prepared.original_sizes)),
      polygon_step_(prepared.polygon_step),
      crease_steps_(prepared.crease_steps),
      steps_(prepared.steps),
      topology_(prepared.mesh, prepared.boundary) {
  refinement_ = std::move(prepared.refinement);
  hierarchy_ = std::move(prepared.hierarchy);
  prepared_ = std::move(prepared.mesh);
  patches_ = std::move(prepared.patches);
  tree_ = std::move(prepared.tree);
  feature_levels_ = prepared.feature_levels;
  feature_faces_ = prepared.feature_faces;
  if (tables_.descent()) descent_ = std::make_unique<QuadPatchDescent>(tables_);
  centre_weights_.resize(static_cast<std::size_t>(tables_.rates().back()) + 1);
  for (int n : tables_.rates()) {
    auto& w = centre_weights_[static_cast<std::size_t>(n)];
    w.resize(4 * static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) tables_.regular_weights(n, 2L * i + 1, w.data() + 4 * i);
  }
  if (tables_.has_regular_derivatives()) {
    centre_derivative_weights_.resize(centre_weights_.size());
    for (int n : tables_.rates()) {
      auto& w = centre_derivative_weights_[static_cast<std::size_t>(n)];
      w.resize(4 * static_cast<std::size_t>(n));
      for (int i = 0; i < n; ++i) tables_.regular_derivative_weights(n, 2L * i + 1, w.data() + 4 * i);
    }
  }
}

std::string QuadFamily::preparation() const {
  std::string out = polygon_step_ ? "the polygon step" : "";
  if (steps_ > 0 || out.empty()) {
    if (!out.empty()) out += " and ";
    out += std::to_string(steps_) + " subdivision step" + (steps_ == 1 ? "" : "s");
  }
  if (crease_steps_ > 0) {
    out += " (" + std::to_string(crease_steps_) + " of them with the creases' sharp rules)";
  }
  if (feature_levels_ > 0)
    out += ", then " + std::to_string(feature_levels_) + " level" + (feature_levels_ == 1 ? "" : "s") +
           " refined round the semi-sharp features (" + std::to_string(feature_faces_) + " faces)";
  return out;
}

FaceDomain QuadFamily::domain(std::size_t face) const { return FaceDomain::of(SchemeFamily::Quad, original_sizes_[face]); }

namespace {

// J <- L J for the linear part L = [[a, b], [c, d]] of one step.
void compose(std::array<double, 4>* j, double a, double b, double c, double d) {
  if (!j) return;
  const std::array<double, 4> m = *j;
  *j = {a * m[0] + b * m[2], a * m[1] + b * m[3], c * m[0] + d * m[2], c * m[1] + d * m[3]};
}

// The linear part of quadrant()'s child c (child coordinates in the parent's) and of a patch rotation r.
void compose_quadrant(std::array<double, 4>* j, int c) {
  switch (c) {
    case 0: compose(j, 2, 0, 0, 2); break;    // (2u, 2v)
    case 1: compose(j, 0, 2, -2, 0); break;   // (2v, 2 - 2u)
    case 2: compose(j, -2, 0, 0, -2); break;  // (2 - 2u, 2 - 2v)
    default: compose(j, 0, -2, 2, 0); break;  // (2 - 2v, 2u)
  }
}
void compose_rotation(std::array<double, 4>* j, int r) {
  switch (r) {
    case 0: break;
    case 1: compose(j, 0, 1, -1, 0); break;   // (v, 1 - u)
    case 2: compose(j, -1, 0, 0, -1); break;  // (1 - u, 1 - v)
    default: compose(j, 0, -1, 1, 0); break;  // (1 - v, u)
  }
}

}  // namespace

template <class P>
std::pair<std::size_t, std::array<P, 2>> QuadFamily::locate_any(std::size_t face, P u, P v, Jacobian* jacobian) const {
  std::array<P, 2> p{u, v};
  if (jacobian) *jacobian = {1, 0, 0, 1};
  for (std::size_t level = 0; level < hierarchy_.levels.size(); ++level) {
    const std::size_t first = hierarchy_.levels[level].child_offsets[face];
    if (level == 0 && polygon_step_ && original_sizes_[face] != 4) {
      std::array<P, 2> local;
      face = first + static_cast<std::size_t>(subface(domain(face), p[0], p[1], local));
      p = local;
      compose(jacobian, 2, 0, 0, 2);  // the tile, doubled
      continue;
    }
    const auto [c, child] = quadrant(p[0], p[1]);
    face = first + static_cast<std::size_t>(c);
    p = child;
    compose_quadrant(jacobian, c);
  }
  while (refined(face)) {  // down the levels refined round semi-sharp features, as the steps above
    const auto [c, child] = quadrant(p[0], p[1]);
    face = tree_.child(face, c);
    p = child;
    compose_quadrant(jacobian, c);
  }
  return {face, p};
}

std::pair<std::size_t, ExactParameter> QuadFamily::locate(std::size_t face, const ExactParameter& at) const {
  const auto [prepared, p] = locate_any(face, at.u, at.v);
  return {prepared, {p[0], p[1]}};
}

std::pair<std::size_t, std::array<double, 2>> QuadFamily::locate(std::size_t face, double u, double v) const {
  return locate_any(face, u, v);
}

template <class P>
std::pair<std::size_t, std::array<P, 2>> QuadFamily::patch_parameter(std::size_t face, P u, P v, Jacobian* jacobian) const {
  const auto [pf, p] = locate_any(face, u, v, jacobian);
  compose_rotation(jacobian, patches_[pf].rotation);
  // Into the patch's own coordinates (the extraordinary vertex at (0, 0)).
  std::array<P, 2> q;
  switch (patches_[pf].rotation) {
    case 0: q = p; break;
    case 1: q = {p[1], from(1, p[0])}; break;
    case 2: q = {from(1, p[0]), from(1, p[1])}; break;
    default: q = {from(1, p[1]), p[0]}; break;
  }
  return {pf, q};
}

template <class P>
Approximation QuadFamily::descend(std::size_t face, P u, P v, double tolerance, const Point* prepared) const {
  const QuadPatchDescent& descent = checked_descent();
  const auto [pf, q] = patch_parameter(face, u, v);
  const QuadPatch& patch = patches_[pf];
  std::vector<Point> points = gather_points(patch.points, prepared);
  return descent.evaluate(patch.valence, points, q[0], q[1], tolerance);
}

template <class P>
bool QuadFamily::descent_stencil(std::size_t face, P u, P v, PatchStencil& out) const {
  if (!descent_) return false;
  try {
    const auto located = patch_parameter(face, u, v);  // not a structured binding: lambdas capture it (clang 14)
    const std::size_t pf = located.first;
    const std::array<P, 2> q = located.second;
    const QuadPatch& patch = patches_[pf];
    return linear_stencil(pf, patch.points, [&](std::vector<Point>& unit) { return descent_->evaluate(patch.valence, unit, q[0], q[1], 0.0); }, out);
  } catch (const ParameterOverflow&) {  // beyond 64-bit fractions: no exact row
    return false;
  }
}

bool QuadFamily::real_stencil(std::size_t face, double u, double v, PatchStencil& out) const {
  return descent_stencil(face, u, v, out);
}

const QuadPatchDescent& QuadFamily::checked_descent() const {
  if (!descent_)
    throw EvaluationError("these tables hold no patch subdivision (exact JSON tables without descent data): it needs the "
                          ".sgs file, or tables from this stencilgen");
  return *descent_;
}

bool QuadFamily::hull_bounds() const { return checked_descent().nonnegative(); }

void QuadFamily::root(std::size_t prepared_face, const Point* prepared, SubPatch& out) const {
  const QuadPatch& patch = patches_[prepared_face];
  out.face = prepared_face;
  out.node = prepared_face;
  out.kind = refined(prepared_face) ? kRefinedKind : patch.valence;
  out.positions = prepared;
  gather_points(patch.points, prepared, out.points);
  out.domain = SubDomain::unit(false);
}

SubDomain QuadFamily::child_domain(const SubDomain& parent, int c, int rotation) {
  // Own coordinates (patch coordinates when rotated) -> the child face's -> the parent's -> through `parent`.
  return mapped_domain(parent, [&](double X, double Y) {
    double u = 0, v = 0;
    QuadPatch::from_patch(rotation, X, Y, u, v);
    to_parent(c, u, v);
    return std::array<double, 2>{u, v};
  });
}

SubPatch QuadFamily::leaf_patch(const SubPatch& in, double x, double y) const {
  auto [X, Y] = in.domain.local(x, y);
  in.domain.clamp_local(X, Y);
  std::size_t node = in.node;
  SubDomain domain = in.domain;
  while (refined(node)) {  // as locate_any's descent of the tree
    const auto [c, child] = quadrant(X, Y);
    X = child[0], Y = child[1];
    node = tree_.child(node, c);
    domain = child_domain(domain, c, refined(node) ? 0 : patches_[node].rotation);
  }
  SubPatch out;
  const QuadPatch& patch = patches_[node];
  out.face = in.face;
  out.node = node;
  out.kind = patch.valence;
  out.positions = in.positions;
  gather_points(patch.points, in.positions, out.points);
  into_frame_of(in, patches_[in.node].points[0], out.points);
  out.domain = domain;
  return out;
}

int QuadFamily::split(const SubPatch& in, SubPatch* children) const {
  if (in.kind == kRefinedKind) {  // the node's four children, leaves with their patches
    for (int c = 0; c < 4; ++c) {
      SubPatch& out = children[c];
      const std::size_t child = tree_.child(in.node, c);
      const QuadPatch& patch = patches_[child];
      out.face = in.face;
      out.node = child;
      out.positions = in.positions;
      out.kind = refined(child) ? kRefinedKind : patch.valence;
      gather_points(patch.points, in.positions, out.points);
      into_frame_of(in, patches_[in.node].points[0], out.points);
      out.domain = child_domain(in.domain, c, refined(child) ? 0 : patch.rotation);
    }
    return 4;
  }
  const QuadPatchDescent& d = checked_descent();
  for (int c = 0; c < 4; ++c) {
    const int cx = c & 1, cy = c >> 1;
    SubPatch& out = children[c];
    d.child(in.kind, in.points, cx, cy, out.points, out.kind);
    out.face = in.face;
    out.node = in.node;
    out.positions = in.positions;
    // The quadrant (cx, cy) of the patch's own square (axes along the patch's, or turned below a refined face).
    out.domain = in.domain;
    out.domain.x_axis = {in.domain.x_axis[0] / 2, in.domain.x_axis[1] / 2};
    out.domain.y_axis = {in.domain.y_axis[0] / 2, in.domain.y_axis[1] / 2};
    out.domain.origin = in.domain.at(cx * 0.5, cy * 0.5);
  }
  return 4;
}

Approximation QuadFamily::evaluate(const SubPatch& in, double x, double y, double tolerance) const {
  if (in.kind == kRefinedKind) return evaluate(leaf_patch(in, x, y), x, y, tolerance);
  std::vector<Point> points = in.points;
  // The sub-patch's own parameters; exact fractions where the double is one (the descent then lands exactly).
  auto [sx, sy] = in.domain.local(x, y);
  in.domain.clamp_local(sx, sy);
  const auto fx = exact_fraction(sx), fy = exact_fraction(sy);
  if (fx && fy) return checked_descent().evaluate(in.kind, points, *fx, *fy, tolerance);
  return checked_descent().evaluate(in.kind, points, sx, sy, tolerance);
}

bool QuadFamily::derivatives(const SubPatch& in, double& x, double& y, Derivatives& out) const {
  if (in.kind == kRefinedKind) return derivatives(leaf_patch(in, x, y), x, y, out);
  const QuadPatchDescent& descent = checked_descent();
  auto [sx, sy] = in.domain.local(x, y);
  in.domain.clamp_local(sx, sy);
  std::vector<Point> points = in.points;
  if (descent.polynomial_regular()) {
    if (in.kind != 4 && sx == 0 && sy == 0) return false;  // no parametric derivative at the extraordinary vertex
    try {
      out = descent.derivatives(in.kind, points, sx, sy);
    } catch (const EvaluationError&) {  // within 2^-64 of it: none in doubles either (the caller takes differences)
      return false;
    }
  } else {
    // phi and phi' are stored on 1/(2N) for the largest rate N: the nearest such point of the sub-patch.
    if (!tables_.has_regular_derivatives()) return false;
    const std::int64_t grid = 2 * static_cast<std::int64_t>(*std::max_element(tables_.rates().begin(), tables_.rates().end()));
    const std::int64_t i = std::llround(sx * static_cast<double>(grid)), j = std::llround(sy * static_cast<double>(grid));
    if (in.kind != 4 && i == 0 && j == 0) return false;
    out = descent.derivatives(in.kind, points, Fraction::make(i, grid), Fraction::make(j, grid));
    sx = static_cast<double>(i) / static_cast<double>(grid), sy = static_cast<double>(j) / static_cast<double>(grid);
  }
  const auto at = in.domain.at(sx, sy);
  x = at[0], y = at[1];
  // To the patch's coordinates: d/dx = dX/dx d/dX + dY/dx d/dY (a scaled square, turned below a refined face).
  const auto inv = in.domain.inverse_jacobian();
  for (int k = 0; k < 3; ++k) {
    const double dX = out.du[k], dY = out.dv[k];
    out.du[k] = inv[0] * dX + inv[2] * dY;
    out.dv[k] = inv[1] * dX + inv[3] * dY;
  }
  return true;
}

const AffineParameters* QuadFamily::affine_parameters(int kind) const {
  if (kind != 4 || !descent_ || !descent_->nonnegative()) return nullptr;
  std::call_once(affine_once_, [this] {
    // A regular patch's point (i, j), i, j in -1..2, sits at (j + 1) * 4 + (i + 1)
    // (patch_descent.hpp) and, for a scheme that reproduces linear functions,
    // at the parameter (i - c, j - c), c the scheme's shift (0 for primal ones).
    // c is read from an evaluation of the patch whose points are their own (i,
    // j, 1), and the reproduction checked at further parameters: the largest
    // deviation found becomes the residual (a scheme without it gets none).
    SubPatch grid;
    grid.kind = 4;
    for (int j = -1; j <= 2; ++j)
      for (int i = -1; i <= 2; ++i) grid.points.push_back({double(i), double(j), 1.0});
    const double shift = evaluate(grid, 0.5, 0.5, 1e-15).point[0] - 0.5;
    auto out = std::make_unique<AffineParameters>();
    for (const Point& p : grid.points) out->at.push_back({p[0] - shift, p[1] - shift});
    double residual = 0;
    for (double x : {0.0, 0.125, 0.3, 0.5, 0.77, 1.0})
      for (double y : {0.0, 0.2, 0.5, 0.625, 0.9, 1.0}) {
        const Point s = evaluate(grid, x, y, 1e-15).point;
        residual = std::max({residual, std::fabs(s[0] - shift - x), std::fabs(s[1] - shift - y), std::fabs(s[2] - 1)});
      }
    out->residual = residual;
    if (residual < 1e-9) affine_ = std::move(out);  // else the scheme does not reproduce linear functions
  });
  return affine_.get();
}

const PolynomialPatch* QuadFamily::polynomial_patch(int kind) const {
  if (kind != 4 || !descent_ || !descent_->polynomial_regular() || !descent_->nonnegative()) return nullptr;
  std::call_once(polynomial_once_, [this] {
    // The regular patch is the tensor product of the curve's basis pieces on
    // [0, 1] (QuadDescent::basis): point (i, j), i, j in -1..2, at (j + 1) * 4
    // + (i + 1), weighs phi_i(X) phi_j(Y). A sub-patch of the regular kind has
    // the same form over its own unit square (its children are regular patches).
    const QuadDescent& d = *tables_.descent();
    auto out = std::make_unique<PolynomialPatch>();
    out->degree = d.degree;
    for (int f = 0; f <= d.degree; ++f)
      for (int e = 0; e <= d.degree; ++e) out->monomials.push_back({e, f});
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) {
        std::vector<double> c;
        for (const auto& m : out->monomials)
          c.push_back(d.basis[static_cast<std::size_t>(i)][static_cast<std::size_t>(m[0])] *
                      d.basis[static_cast<std::size_t>(j)][static_cast<std::size_t>(m[1])]);
        out->coefficients.push_back(std::move(c));
      }
    polynomial_ = std::move(out);
  });
  return polynomial_.get();
}

FaceParameterReal QuadFamily::original(std::size_t face, double x, double y) const {
  // Patch coordinates back to the node's own (undo the rotation).
  double u = 0, v = 0;
  QuadPatch::from_patch(patches_[face].rotation, x, y, u, v);
  return original_of_face(face, u, v);
}

FaceParameterReal QuadFamily::original_of_face(std::size_t face, double u, double v) const {
  // Up the levels refined round semi-sharp features to the prepared face.
  while (face >= prepared_.face_count()) {
    to_parent(tree_.which(face), u, v);
    face = tree_.parent[face];
  }
  // Up the hierarchy: each child's parameter to its parent's (the inverse of quadrant(), or a sub-face's tile).
  for (std::size_t level = hierarchy_.levels.size(); level-- > 0;) {
    const auto& offsets = hierarchy_.levels[level].child_offsets;
    const std::size_t parent = static_cast<std::size_t>(std::upper_bound(offsets.begin(), offsets.end(), face) - offsets.begin()) - 1;
    const int c = static_cast<int>(face - offsets[parent]);
    if (level == 0 && polygon_step_ && original_sizes_[parent] != 4) {
      const FaceDomain d = domain(parent);
      u = c % d.u_tiles + u / 2, v = c / d.u_tiles + v / 2;
    } else {
      to_parent(c, u, v);
    }
    face = parent;
  }
  domain(face).clamp(u, v);  // the steps up round: a border point may land a few ulps outside
  return {face, u, v};
}

Approximation QuadFamily::evaluate(std::size_t face, const ExactParameter& at, double tolerance, const Point* prepared) const {
  try {
    return descend(face, at.u, at.v, tolerance, prepared);
  } catch (const ParameterOverflow&) {  // beyond 64-bit fractions: the nearest double
    Approximation a = descend(face, at.u.to_double(), at.v.to_double(), tolerance, prepared);
    a.exact = false;
    return a;
  }
}

Approximation QuadFamily::evaluate(std::size_t face, double u, double v, double tolerance, const Point* prepared) const {
  // A double is an exact dyadic fraction: evaluated exactly where the tables reach it.
  const auto fu = exact_fraction(u), fv = exact_fraction(v);
  if (fu && fv) return descend(face, *fu, *fv, tolerance, prepared);
  return descend(face, u, v, tolerance, prepared);
}

template <class P>
std::pair<int, std::array<P, 2>> QuadFamily::patch_points(std::size_t face, P u, P v, const Point* prepared, Jacobian& j,
                                                          std::vector<Point>& points) const {
  const auto located = patch_parameter(face, u, v, &j);
  const QuadPatch& patch = patches_[located.first];
  points.resize(patch.points.size());
  for (std::size_t h = 0; h < points.size(); ++h) points[h] = prepared[patch.points[h]];
  return {patch.valence, located.second};
}

template <class P>
Derivatives QuadFamily::derivatives_any(std::size_t face, P u, P v, const Point* prepared) const {
  const QuadPatchDescent& descent = checked_descent();
  Jacobian j{};
  std::vector<Point> points;
  const auto [valence, at] = patch_points(face, u, v, prepared, j, points);
  const Derivatives d = descent.derivatives(valence, points, at[0], at[1]);
  // Chain rule: d/du = f_x dx/du + f_y dy/du, d/dv likewise.
  Derivatives out;
  out.point = d.point;
  for (std::size_t c = 0; c < 3; ++c) {
    out.du[c] = d.du[c] * j[0] + d.dv[c] * j[2];
    out.dv[c] = d.du[c] * j[1] + d.dv[c] * j[3];
  }
  return out;
}

Derivatives QuadFamily::derivatives(std::size_t face, const ExactParameter& at, const Point* prepared) const {
  try {
    return derivatives_any(face, at.u, at.v, prepared);
  } catch (const ParameterOverflow&) {
    throw EvaluationError("the parameter " + at.str() + " needs fractions beyond 64 bits on the way to a regular patch");
  }
}

Derivatives QuadFamily::derivatives(std::size_t face, double u, double v, const Point* prepared) const {
  const auto fu = exact_fraction(u), fv = exact_fraction(v);
  if (fu && fv) return derivatives(face, ExactParameter{*fu, *fv}, prepared);
  return derivatives_any(face, u, v, prepared);
}

namespace {
bool is_zero(const Fraction& x) { return x.num == 0; }
bool is_zero(double x) { return x == 0; }
}  // namespace

template <class P>
Point QuadFamily::normal_any(std::size_t face, P u, P v, const Point* prepared) const {
  Jacobian j{};
  std::vector<Point> points;
  const auto [valence, at] = patch_points(face, u, v, prepared, j, points);
  if (valence == 4 || !is_zero(at[0]) || !is_zero(at[1])) return derivatives_any(face, u, v, prepared).normal();
  // The extraordinary vertex: t_u.P x t_v.P, in the patch's coordinates (every
  // map from the face to the patch keeps the orientation: doublings, quarter
  // turns, the patch's rotation).
  const QuadDescent::Valence& d = tables_.descent(valence);
  if (d.tangent_u.size() != points.size() && is_sector_kind(valence)) {
    const SectorKey s = sector_of(valence);
    if (s.rule == SectorRule::Dart)
      throw EvaluationError("the tables hold no tangent stencils at this dart (the end of an infinitely sharp crease), so "
                            "there is no normal at it: regenerate them with this stencilgen");
    if (s.rule == SectorRule::Cone) throw EvaluationError("a cone point has no tangent plane, so there is no normal at it");
    throw EvaluationError(s.rule == SectorRule::Corner ? "a corner has no tangent plane, so there is no normal at it"
                                   : "this scheme's boundary rules give no tangent plane at a boundary vertex in " +
                                         std::to_string(s.faces) + " face" + (s.faces == 1 ? "" : "s") +
                                         " (Reif's condition fails there: `stencilgen analyze` shows the spectrum), so there is "
                                         "no normal at it; the surface round it evaluates as anywhere else");
  }
  if (d.tangent_u.size() != points.size())
    throw EvaluationError("the tables hold no tangent stencils at the " + kind_name(valence) +
                          ", so there is no normal at the extraordinary vertex (exact JSON tables from before descent "
                          "version 2, or a scheme whose subdominant eigenvalue is not a real double one)");
  Derivatives tangents;  // only its du x dv is used
  for (std::size_t h = 0; h < points.size(); ++h)
    for (std::size_t c = 0; c < 3; ++c) tangents.du[c] += d.tangent_u[h] * points[h][c], tangents.dv[c] += d.tangent_v[h] * points[h][c];
  return tangents.normal();
}

Point QuadFamily::normal(std::size_t face, const ExactParameter& at, const Point* prepared) const {
  try {
    return normal_any(face, at.u, at.v, prepared);
  } catch (const ParameterOverflow&) {
    throw EvaluationError("the parameter " + at.str() + " needs fractions beyond 64 bits on the way to a regular patch");
  }
}

Point QuadFamily::normal(std::size_t face, double u, double v, const Point* prepared) const {
  const auto fu = exact_fraction(u), fv = exact_fraction(v);
  if (fu && fv) return normal(face, ExactParameter{*fu, *fv}, prepared);
  return normal_any(face, u, v, prepared);
}

template <class P>
SecondDerivatives QuadFamily::second_derivatives_any(std::size_t face, P u, P v, const Point* prepared) const {
  const QuadPatchDescent& descent = checked_descent();
  Jacobian j{};
  std::vector<Point> points;
  const auto [valence, at] = patch_points(face, u, v, prepared, j, points);
  const SecondDerivatives d = descent.second_derivatives(valence, points, at[0], at[1]);
  // Chain rule through the linear map (x, y)(u, v): x_u = j0, x_v = j1, y_u = j2, y_v = j3.
  SecondDerivatives out;
  out.point = d.point;
  for (std::size_t c = 0; c < 3; ++c) {
    out.du[c] = d.du[c] * j[0] + d.dv[c] * j[2];
    out.dv[c] = d.du[c] * j[1] + d.dv[c] * j[3];
    out.duu[c] = d.duu[c] * j[0] * j[0] + 2 * d.duv[c] * j[0] * j[2] + d.dvv[c] * j[2] * j[2];
    out.duv[c] = d.duu[c] * j[0] * j[1] + d.duv[c] * (j[0] * j[3] + j[2] * j[1]) + d.dvv[c] * j[2] * j[3];
    out.dvv[c] = d.duu[c] * j[1] * j[1] + 2 * d.duv[c] * j[1] * j[3] + d.dvv[c] * j[3] * j[3];
  }
  return out;
}

SecondDerivatives QuadFamily::second_derivatives(std::size_t face, const ExactParameter& at, const Point* prepared) const {
  try {
    return second_derivatives_any(face, at.u, at.v, prepared);
  } catch (const ParameterOverflow&) {
    throw EvaluationError("the parameter " + at.str() + " needs fractions beyond 64 bits on the way to a regular patch");
  }
}

SecondDerivatives QuadFamily::second_derivatives(std::size_t face, double u, double v, const Point* prepared) const {
  const auto fu = exact_fraction(u), fv = exact_fraction(v);
  if (fu && fv) return second_derivatives(face, ExactParameter{*fu, *fv}, prepared);
  return second_derivatives_any(face, u, v, prepared);
}

bool QuadFamily::stencil(std::size_t face, const ExactParameter& at, PatchStencil& out) const {
  const auto [prepared, p] = locate(face, at);
  const QuadPatch& patch = patches_[prepared];
  const ExactParameter q = patch.to_patch(p);
  // The smallest stored rate n whose grid 1/(2n) holds both coordinates with
  // equal parity: a node (both even) or a cell centre (both odd).
  for (int n : tables_.rates()) {
    const std::int64_t g = 2 * static_cast<std::int64_t>(n);
    if (g % q.u.den != 0 || g % q.v.den != 0) continue;
    const std::int64_t a = q.u.num * (g / q.u.den), b = q.v.num * (g / q.v.den);
    if (((a ^ b) & 1) != 0) continue;
    out.face = prepared;
    out.points = patch.points.data();
    out.size = patch.points.size();
    if ((a & 1) == 0) tables_.node_stencil(patch.valence, n, static_cast<int>(a / 2), static_cast<int>(b / 2), out.storage.data());
    else tables_.centre_stencil(patch.valence, n, static_cast<int>(a / 2), static_cast<int>(b / 2), out.storage.data());
    out.weights = out.storage.data();
    return true;
  }
  return descent_stencil(face, at.u, at.v, out);
}

std::size_t QuadFamily::leaf_of(std::size_t node, long& a, long& b, long d) const {
  while (refined(node)) {  // quadrant() on (a, b) / d
    const bool right = 2 * a > d, top = 2 * b > d;
    const long x = 2 * a - (right ? d : 0), y = 2 * b - (top ? d : 0);
    const int c = !top ? (right ? 1 : 0) : (right ? 2 : 3);
    switch (c) {
      case 0: a = x, b = y; break;
      case 1: a = y, b = d - x; break;
      case 2: a = d - x, b = d - y; break;
      default: a = d - y, b = x; break;
    }
    node = tree_.child(node, c);
  }
  return node;
}

Point QuadFamily::refined_point(std::size_t face, long a, long b, int n, const Point* prepared) const {
  const std::size_t leaf = leaf_of(face, a, b, 2L * n);
  const QuadPatch& p = patches_[leaf];
  long pa = 0, pb = 0;
  p.to_patch(a, b, 2L * n, pa, pb);
  // Below a refined face every such point is a node of rate n (one step doubles the odd centres).
  std::array<double, limits::kMaxPatchPoints> w{};
  if (((pa | pb) & 1) == 0) tables_.node_stencil(p.valence, n, static_cast<int>(pa / 2), static_cast<int>(pb / 2), w.data());
  else tables_.centre_stencil(p.valence, n, static_cast<int>(pa / 2), static_cast<int>(pb / 2), w.data());
  return stencil_sum(w.data(), p.points.data(), p.points.size(), prepared);
}

bool QuadFamily::refined_regular_normal(std::size_t face, long a, long b, int n, const Point* prepared, Point& normal) const {
  if (!tables_.has_regular_derivatives()) return false;
  const std::size_t leaf = leaf_of(face, a, b, 2L * n);
  const QuadPatch& p = patches_[leaf];
  if (p.valence != 4) return false;
  long pa = 0, pb = 0;
  p.to_patch(a, b, 2L * n, pa, pb);
  // Quarter turns and doublings keep the orientation: du x dv in the leaf's coordinates points as on the face.
  double wx[4], wy[4], dx[4], dy[4];
  tables_.regular_weights(n, pa, wx), tables_.regular_weights(n, pb, wy);
  tables_.regular_derivative_weights(n, pa, dx), tables_.regular_derivative_weights(n, pb, dy);
  Derivatives d;
  for (int q = 0; q < 4; ++q)
    for (int r = 0; r < 4; ++r) {
      const Point& P = prepared[p.points[static_cast<std::size_t>(q * 4 + r)]];
      for (std::size_t k = 0; k < 3; ++k) d.du[k] += dx[r] * wy[q] * P[k], d.dv[k] += wx[r] * dy[q] * P[k];
    }
  normal = d.normal();
  return true;
}

// The n^2 cell centres of a regular face, tensor-product form: rows R[q][i] =
// sum_c wx(i)[c] P(c, q), then each point sums 4 rows with the weights of its
// row. N > 0 fixes n at compile time (short loops unrolled), N = 0 reads it.
template <int N>
void regular_centres(const QuadPatch& p, const double* wx, int n_runtime, const Point* pos, std::array<float, 3>* out,
                     std::vector<Point>& rows) {
  const int n = N > 0 ? N : n_runtime;
  rows.resize(4 * static_cast<std::size_t>(n));
  for (int q = 0; q < 4; ++q) {
    const Point& P0 = pos[p.points[static_cast<std::size_t>(q * 4)]];
    const Point& P1 = pos[p.points[static_cast<std::size_t>(q * 4 + 1)]];
    const Point& P2 = pos[p.points[static_cast<std::size_t>(q * 4 + 2)]];
    const Point& P3 = pos[p.points[static_cast<std::size_t>(q * 4 + 3)]];
    for (int i = 0; i < n; ++i) {
      const double* w = wx + 4 * i;
      rows[static_cast<std::size_t>(q * n + i)] = {w[0] * P0[0] + w[1] * P1[0] + w[2] * P2[0] + w[3] * P3[0],
                                                   w[0] * P0[1] + w[1] * P1[1] + w[2] * P2[1] + w[3] * P3[1],
                                                   w[0] * P0[2] + w[1] * P1[2] + w[2] * P2[2] + w[3] * P3[2]};
    }
  }
  const Point* r0 = rows.data();
  const Point* r1 = r0 + n;
  const Point* r2 = r1 + n;
  const Point* r3 = r2 + n;
  for (int j = 0; j < n; ++j) {
    const double* wy = wx + 4 * j;  // same weights: the grid is square
    for (int i = 0; i < n; ++i)
      out[j * n + i] = {static_cast<float>(wy[0] * r0[i][0] + wy[1] * r1[i][0] + wy[2] * r2[i][0] + wy[3] * r3[i][0]),
                        static_cast<float>(wy[0] * r0[i][1] + wy[1] * r1[i][1] + wy[2] * r2[i][1] + wy[3] * r3[i][1]),
                        static_cast<float>(wy[0] * r0[i][2] + wy[1] * r1[i][2] + wy[2] * r2[i][2] + wy[3] * r3[i][2])};
  }
}

void QuadFamily::points(const TessellationLayout& layout, std::size_t begin, std::size_t end, const Point* pos,
                        std::array<float, 3>* out_all) const {
  thread_local std::vector<Point> rows, local, reflected;
  for (std::size_t f = begin; f != end; ++f) {
    if (!layout.holes.empty() && layout.holes[f]) continue;  // no points
    const QuadPatch& p = patches_[f];
    const int n = layout.rates[f];
    std::array<float, 3>* out = out_all + layout.point_offsets[f];
    if (refined(f)) {  // point by point from the leaves
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const Point q = refined_point(f, 2L * i + 1, 2L * j + 1, n, pos);
          out[j * n + i] = {static_cast<float>(q[0]), static_cast<float>(q[1]), static_cast<float>(q[2])};
        }
      continue;
    }
    if (p.valence == 4) {
      const double* wx = centre_weights_[static_cast<std::size_t>(n)].data();
      switch (n) {  // small rates unrolled: their per-face loops are short
        case 1: regular_centres<1>(p, wx, 1, pos, out, rows); break;
        case 2: regular_centres<2>(p, wx, 2, pos, out, rows); break;
        case 3: regular_centres<3>(p, wx, 3, pos, out, rows); break;
        case 4: regular_centres<4>(p, wx, 4, pos, out, rows); break;
        case 6: regular_centres<6>(p, wx, 6, pos, out, rows); break;
        case 8: regular_centres<8>(p, wx, 8, pos, out, rows); break;
        default: regular_centres<0>(p, wx, n, pos, out, rows); break;
      }
      continue;
    }
    const std::size_t m = p.points.size();
    // The control points, contiguous, and in reflected order for mirrored stencils.
    local.resize(m);
    reflected.resize(m);
    const std::uint32_t* reflect = tables_.reflection(p.valence);  // null for a boundary sector (never mirrored)
    for (std::size_t h = 0; h < m; ++h) local[h] = pos[p.points[h]];
    if (reflect)
      for (std::size_t h = 0; h < m; ++h) reflected[h] = local[reflect[h]];
    const QuadTables::CentreGrid grid = tables_.centre_grid(p.valence, n);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        long pa = 0, pb = 0;
        p.to_patch(2L * i + 1, 2L * j + 1, 2L * n, pa, pb);
        bool mirrored = false;
        const double* wt = grid.at(static_cast<int>(pa / 2), static_cast<int>(pb / 2), mirrored);
        const Point* P = mirrored ? reflected.data() : local.data();
        double x = 0, y = 0, z = 0;
        for (std::size_t h = 0; h < m; ++h) x += wt[h] * P[h][0], y += wt[h] * P[h][1], z += wt[h] * P[h][2];
        out[j * n + i] = {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
      }
  }
}

std::shared_ptr<const std::vector<double>> QuadFamily::centre_derivatives(int valence, int n) const {
  {
    std::lock_guard lock(centre_derivatives_mutex_);
    const auto it = centre_derivatives_.find({valence, n});
    if (it != centre_derivatives_.end()) return it->second;
  }
  // Layout: centre (i, j) at (j n + i) * 2m: m weights of d/dx, then m of d/dy.
  // The derivatives are linear in the points (derivative_weights_by_linearity).
  const QuadPatchDescent& descent = checked_descent();
  const std::size_t m = static_cast<std::size_t>(QuadTables::points(valence));
  auto weights = std::make_shared<std::vector<double>>(static_cast<std::size_t>(n) * static_cast<std::size_t>(n) * 2 * m);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      derivative_weights_by_linearity(
          m,
          [&](std::vector<Point>& unit) {
            return descent.derivatives(valence, unit, Fraction::make(2L * i + 1, 2L * n), Fraction::make(2L * j + 1, 2L * n));
          },
          weights->data() + (static_cast<std::size_t>(j) * static_cast<std::size_t>(n) + static_cast<std::size_t>(i)) * 2 * m);
  std::lock_guard lock(centre_derivatives_mutex_);
  return centre_derivatives_.emplace(std::pair{valence, n}, std::move(weights)).first->second;
}

void QuadFamily::normals(const TessellationLayout& layout, std::size_t begin, std::size_t end, const Point* pos,
                         std::array<float, 3>* out_all) const {
  // Each cell centre's derivatives in the patch's own coordinates: the
  // patch's rotation has determinant +1, so du x dv there points the same way
  // as on the face.
  thread_local std::vector<Point> local;
  thread_local RegularFaceScratch regular;
  for (std::size_t f = begin; f != end; ++f) {
    if (!layout.holes.empty() && layout.holes[f]) continue;  // no points
    const QuadPatch& p = patches_[f];
    const int n = layout.rates[f];
    std::array<float, 3>* out = out_all + layout.point_offsets[f];
    if (refined(f)) {  // point by point: regular leaves from their stencils, others from the original face
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          Point q;
          if (!refined_regular_normal(f, 2L * i + 1, 2L * j + 1, n, pos, q)) {
            // No cell centre is a vertex, where normals may fail.
            const FaceParameterReal at = original_of_face(f, (i + 0.5) / n, (j + 0.5) / n);
            q = normal(at.face, at.u, at.v, pos);
          }
          out[j * n + i] = {static_cast<float>(q[0]), static_cast<float>(q[1]), static_cast<float>(q[2])};
        }
      continue;
    }
    if (p.valence == 4 && !centre_derivative_weights_.empty()) {
      regular_face_samples(p, centre_weights_[static_cast<std::size_t>(n)].data(),
                           centre_derivative_weights_[static_cast<std::size_t>(n)].data(), n, pos, nullptr, out, regular);
      continue;
    }
    const std::size_t m = p.points.size();
    const std::shared_ptr<const std::vector<double>> cached = centre_derivatives(p.valence, n);
    local.resize(m);
    for (std::size_t h = 0; h < m; ++h) local[h] = pos[p.points[h]];
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        long pa = 0, pb = 0;
        p.to_patch(2L * i + 1, 2L * j + 1, 2L * n, pa, pb);
        const double* w = cached->data() + (static_cast<std::size_t>(pb / 2) * static_cast<std::size_t>(n) + static_cast<std::size_t>(pa / 2)) * 2 * m;
        Derivatives d;
        for (std::size_t h = 0; h < m; ++h)
          for (std::size_t k = 0; k < 3; ++k) d.du[k] += w[h] * local[h][k], d.dv[k] += w[m + h] * local[h][k];
        const Point normal = d.normal();
        out[j * n + i] = {static_cast<float>(normal[0]), static_cast<float>(normal[1]), static_cast<float>(normal[2])};
      }
  }
}

void QuadFamily::points_and_normals(const TessellationLayout& layout, std::size_t begin, std::size_t end,
                                    const Point* pos, std::array<float, 3>* positions,
                                    std::array<float, 3>* normals) const {
  // Regular faces: positions and normals from the same rows, in one pass
  // (regular_face_samples); the positions equal points()'s bit for bit.
  thread_local RegularFaceScratch regular;
  for (std::size_t f = begin; f != end; ++f) {
    if (!layout.holes.empty() && layout.holes[f]) continue;  // no points
    const QuadPatch& p = patches_[f];
    const int n = layout.rates[f];
    if (p.valence == 4 && !centre_derivative_weights_.empty() && !refined(f)) {
      const std::size_t at = layout.point_offsets[f];
      regular_face_samples(p, centre_weights_[static_cast<std::size_t>(n)].data(),
                           centre_derivative_weights_[static_cast<std::size_t>(n)].data(), n, pos, positions + at,
                           normals + at, regular);
      continue;
    }
    points(layout, f, f + 1, pos, positions);
    this->normals(layout, f, f + 1, pos, normals);
  }
}

}  // namespace stencil_runtime
