#include "triangle_family.hpp"

#include <algorithm>
#include <memory>
#include <string>
#include <type_traits>

#include "family/crease_step.hpp"
#include "family/semi_sharp_levels.hpp"
#include "stencil_runtime/face_domain.hpp"
#include "family/sharp_cut.hpp"
#include "family/parameter_ops.hpp"
#include "family/stencil_sum.hpp"
#include "boundary_patch.hpp"
#include "sector_patch.hpp"
#include "mesh/polygon_links.hpp"
#include "loop_split.hpp"
#include "triangle_steps.hpp"

namespace stencil_runtime {

struct TriangleFamily::Prepared {
  Refinement refinement;
  FaceHierarchy hierarchy;
  int steps = 0;
  int crease_steps = 0;  // of the steps, those that still had sharp features
  bool boundary = false;
  Connectivity mesh;
  std::vector<TrianglePatch> patches;  // as the last isolation check found them, then the tree's nodes
  PhantomPoints phantoms;              // the points beyond the boundary those patches use
  FeatureTree tree;  // refined round semi-sharp features (triangle_family.hpp)
  int feature_levels = 0;
  std::size_t feature_faces = 0;
};

namespace {

// A face's patch. `topo` is the mesh cut along its infinitely sharp edges
// (family/sharp_cut.hpp), whose boundaries are the mesh's own and its creases;
// `rules` its vertices' rules (`cones`: some are cone points). On a mesh with
// boundaries, a face at one boundary vertex in other than three faces or at a
// corner takes that vertex's sector patch (sector_patch.hpp; two such corners:
// not yet isolated), a face whose corners are all regular the regular patch
// with phantoms (boundary_patch.hpp); the others need the tables' chart walks,
// which stop at the boundary. A face at a vertex marked in `no_surface`
// (OpenSubdiv's `none`: a copy of a vertex on the mesh's own boundary) has no
// surface: where it has no regular patch it gets a placeholder that is never
// evaluated. No patch (nullopt): the face is not isolated yet.
std::optional<TrianglePatch> face_patch(const TriangleTopology& topo, std::size_t f, const TriangleTables& tables,
                                       PhantomPoints& phantoms, const std::vector<char>& no_surface,
                                       const std::vector<SectorRule>& rules, bool cones) {
  const bool at_boundary = topo.touches_boundary(f);
  // A vertex on the boundary in other than three faces, a corner, a dart or
  // a cone point: the sector's patch (sector_patch.hpp).
  int sector_corner = -1, sectors = 0;
  const bool sector_possible = (at_boundary || cones) && !topo.touches_marked(f, no_surface);
  for (int c = 0; c < 3; ++c) {
    const int v = topo.vertex(f, c);
    const SectorRule rule = rules[static_cast<std::size_t>(v)];
    if (slit_end_inside(rule, topo.on_boundary(v))) return std::nullopt;
    if (sector_possible && loop_sector_vertex(topo, v, rule)) ++sectors, sector_corner = c;
  }
  if (sectors > 1) return std::nullopt;
  if (sectors == 1) return loop_sector_patch(topo, f, sector_corner, rules, tables);
  if (at_boundary || (topo.has_boundary() && regular_loop_vertex(topo, topo.vertex(f, 0)) &&
                      regular_loop_vertex(topo, topo.vertex(f, 1)) && regular_loop_vertex(topo, topo.vertex(f, 2)))) {
    std::optional<TrianglePatch> patch = regular_boundary_patch(topo, f, tables, phantoms);
    if (!patch && topo.touches_marked(f, no_surface)) {
      patch.emplace();
      patch->points.assign(tables.layout(6).size(), topo.vertex(f, 0));  // a hole: never evaluated
    }
    return patch;
  }
  return find_triangle_patch(topo, f, tables);
}

bool has_cones(const std::vector<SectorRule>& rules) {
  return std::find(rules.begin(), rules.end(), SectorRule::Cone) != rules.end();
}

bool gather_patches(const TriangleTopology& topo, const TriangleTables& tables, std::vector<TrianglePatch>& patches,
                    PhantomPoints& phantoms, const std::vector<char>& no_surface, const std::vector<SectorRule>& rules) {
  patches.clear();
  patches.reserve(topo.faces());
  phantoms = PhantomPoints{};
  phantoms.first = topo.vertices();
  const bool cones = has_cones(rules);
  for (std::size_t f = 0; f < topo.faces(); ++f) {
    std::optional<TrianglePatch> patch = face_patch(topo, f, tables, phantoms, no_surface, rules, cones);
    if (!patch) return false;
    patches.push_back(std::move(*patch));
  }
  return true;
}

// The vertices of a Loop mesh cut along its infinitely sharp edges (`cut`,
// whose links are `links`), checked once on the input (steps keep every
// vertex's number of faces and rule): inside ones need their valence in the
// tables; one on a boundary of the cut mesh, the mesh's own or a crease, in
// three faces with the crease rule has the regular boundary patch
// (boundary_patch.hpp), any other, every dart and every cone point needs its
// sector's patches in the tables (sector_patch.hpp). With `none`
// (`no_surface`) the faces at the mesh's own boundary have no surface, so any
// vertex will do there.
// Tables written before stencilgen wrote a kind of sector hold none of it,
// not even `first`, its smallest: regenerating, not a larger valence, covers
// the mesh then.
void require_sector_rule(const TriangleTables& tables, const SectorKey& first, const std::string& what, const char* kind,
                         const std::string& scheme) {
  if (!tables.has_sectors() || !tables.sector_code(first))
    throw MeshError(what + ", and the " + scheme + " tables hold no patches for " + kind +
                    " (written before stencilgen wrote them); regenerate them with this stencilgen");
}

void check_loop_vertices(const SharpCut& cut, const PolygonLinks& links, const PolygonLinks& uncut,
                         const std::vector<char>& no_surface, const std::string& scheme, const TriangleTables& tables,
                         ValenceCheck& valences) {
  for (std::size_t v = 0; v < cut.mesh.vertex_count; ++v) {
    const int k = links.valence[v];
    const std::string who = "vertex " + std::to_string(cut.origin[v]);
    if (cut.rule[v] == SectorRule::Cone) {  // inside the cut mesh, its ring closed: one sector for every face
      if (tables.sector_code({SectorRule::Cone, k, 0})) continue;
      const std::string what = who + " is a cone point (infinitely sharp, on no infinitely sharp edge) of valence " +
                               std::to_string(k);
      require_sector_rule(tables, {SectorRule::Cone, 3, 0}, what, "cone points", scheme);
      valences.add_boundary(k, what);
      continue;
    }
    if (!links.boundary[v] && !ends_slit(cut.rule[v])) {
      valences.add_lazy(k, [&] { return who; });
      continue;
    }
    if (!no_surface.empty() && no_surface[v]) continue;  // no surface there: any will do
    const bool own = uncut.boundary[static_cast<std::size_t>(cut.origin[v])] != 0;
    if (cut.rule[v] == SectorRule::Crease && k == 3) continue;  // the regular boundary patch
    // A boundary sector's patch (sector_patch.hpp), every face of it from the tables.
    for (int p = 0; p < k; ++p) {
      const SectorKey key{cut.rule[v], k, p};
      if (tables.sector_code(key)) continue;
      const std::string what =
          cut.rule[v] == SectorRule::Dart ? " ends an infinitely sharp crease (a dart) at valence " + std::to_string(k)
          : cut.rule[v] == SectorRule::Corner
              ? " is a corner in " + std::to_string(k) + (k == 1 ? " face" : " faces") +
                    " (a sharp vertex, three or more boundary or infinitely sharp edges, or with edge-and-corner a "
                    "boundary vertex in one face)"
              : " is on " + std::string(own ? "the boundary in " : "an infinitely sharp crease with ") + std::to_string(k) +
                    (k == 1 ? " face" : " faces") + (own ? "" : " on one side");
      require_sector_rule(tables, {SectorRule::Crease, 1, 0}, who + what, "boundary vertices", scheme);
      if (cut.rule[v] == SectorRule::Dart) require_sector_rule(tables, {SectorRule::Dart, 3, 0}, who + what, "darts", scheme);
      // Tables hold the sectors of up to as many faces as their largest valence: the call that covers it.
      valences.add_boundary(k, who + what);
      break;
    }
  }
}

// The boundary rules of a Loop mesh with boundaries (sqrt(3) refuses them: it splits no edges).
BoundaryRules loop_boundary_rules(const Tables& tables, const MeshFeatures& features) {
  const CurveCreaseRule crease = triangle_crease_rule(tables.triangle(), tables.scheme(), "meshes with boundaries");
  return {crease.centre, crease.neighbour, features.boundary == BoundaryInterpolation::EdgeAndCorner};
}

// The mesh the patches are gathered on: the prepared mesh cut along its
// infinitely sharp edges, when it has any.
struct PatchMesh {
  std::optional<SharpCut> cut;
  std::optional<TriangleTopology> cut_topology;
  std::vector<char> no_surface;  // per vertex of the cut mesh (no_surface_vertices)
  std::vector<SectorRule> rules;  // per vertex of the cut mesh: crease (or none inside), corner, dart, cone

  PatchMesh(const Connectivity& mesh, const TriangleTopology& topo, const LevelSharpness& sharpness, bool edge_and_corner,
            bool no_boundary_surface) {
    if (!sharpness.infinite() && !topo.has_boundary()) {  // closed and nothing to cut: every vertex smooth
      rules.assign(topo.vertices(), SectorRule::Crease);
      return;
    }
    const PolygonLinks links = link_polygons(mesh, true);
    if (sharpness.infinite()) {
      cut = cut_along_sharp_edges(mesh, links, sharpness, edge_and_corner);
      cut_topology.emplace(cut->mesh, link_polygons(cut->mesh, true));
      no_surface = no_surface_vertices(no_boundary_surface, mesh, links, sharpness, *cut);
      rules = cut->rule;
    } else {
      if (no_boundary_surface) no_surface = surfaceless_vertices(mesh, links, sharpness);
      // Nothing to cut: the vertices' rules as the cut gives them (edge-and-corner's corners).
      rules = cut_along_sharp_edges(mesh, links, sharpness, edge_and_corner).rule;
    }
  }
  const TriangleTopology& topology(const TriangleTopology& uncut) const { return cut_topology ? *cut_topology : uncut; }
};

// Cell of the 1-to-9 split (ternary_cells) holding (u, v), and the parameter there.
template <class P>
std::pair<int, std::array<P, 2>> ternary_child(const P& u, const P& v) {
  const P x = multiply(u, 3), y = multiply(v, 3), zero = integer<P>(0), one = integer<P>(1);
  int c = 0;
  for (const TernaryCell& cell : ternary_cells()) {
    std::array<P, 2> q;
    if (cell.down) q = {subtract(add(x, y), integer<P>(cell.a + cell.b + 1)), subtract(integer<P>(cell.a + 1), x)};
    else q = {subtract(x, integer<P>(cell.a)), subtract(y, integer<P>(cell.b))};
    if (compare(q[0], zero) >= 0 && compare(q[1], zero) >= 0 && compare(add(q[0], q[1]), one) <= 0) return {c, q};
    ++c;
  }
  if constexpr (std::is_same_v<P, double>) {  // rounding put it just outside every cell: the nearest
    int best = 0;
    double distance = 1e300;
    std::array<double, 2> at{};
    c = 0;
    for (const TernaryCell& cell : ternary_cells()) {
      std::array<double, 2> q = cell.down ? std::array<double, 2>{x + y - (cell.a + cell.b + 1), cell.a + 1 - x}
                                          : std::array<double, 2>{x - cell.a, y - cell.b};
      const double outside = std::max({0.0, -q[0], -q[1], q[0] + q[1] - 1});
      if (outside < distance) distance = outside, best = c, at = q;
      ++c;
    }
    return {best, at};
  } else if constexpr (std::is_same_v<P, Dual>) {
    throw EvaluationError("parameter " + parameter_text(u.value, v.value) + " lies outside the triangle");
  } else if constexpr (std::is_same_v<P, ExactDual>) {
    throw EvaluationError("parameter (" + u.value.str() + ", " + v.value.str() + ") lies outside the triangle");
  } else {
    throw EvaluationError("parameter (" + u.str() + ", " + v.str() + ") lies outside the triangle");
  }
}

}  // namespace

namespace {

// Where a Loop step puts the edge point of each corner's edge: child c < 3 of
// face f covers corner c and has that edge point second (loop_step).
std::vector<int> loop_step_edge_points(const Connectivity& parent, const Connectivity& child) {
  std::vector<int> out(parent.face_vertices.size());
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = child.face_vertices[3 * (4 * (k / 3) + k % 3) + 1];
  return out;
}

}  // namespace

TriangleFamily::Prepared TriangleFamily::prepare(const Tables& tables, const Connectivity& mesh, const MeshFeatures& features) {
  const TriangleTables& t = tables.triangle();
  TriangleFamily::Prepared out;
  out.refinement = Refinement(mesh.vertex_count);
  out.hierarchy.original_faces = mesh.face_count();
  // A manifold of triangles, closed or with boundaries (names the face, edge or vertex).
  const PolygonLinks links = link_polygons(mesh, true);
  TriangleTopology topo(mesh, links);
  out.boundary = topo.has_boundary();
  const bool edge_and_corner = features.boundary == BoundaryInterpolation::EdgeAndCorner;
  const bool no_boundary_surface = out.boundary && features.boundary == BoundaryInterpolation::None;
  std::optional<BoundaryRules> boundary;
  if (out.boundary) boundary = loop_boundary_rules(tables, features);
  LevelSharpness sharpness = LevelSharpness::of(mesh, features, true);
  CurveCreaseRule crease;
  // Semi-sharp features by whole-mesh steps where they fit the budget, else
  // refined round them after the isolation (refine_round_features).
  bool local = false;
  if (!sharpness.smooth()) {
    crease = triangle_crease_rule(t, tables.scheme(), "creases and corners");  // sqrt(3) refused here
    local = prefer_round_features(mesh, sharpness, 4 * mesh.face_count());
    if (!local) check_crease_steps(mesh.face_count(), 4 * mesh.face_count(), sharpness.max());
  }
  {
    ValenceCheck valences(tables.valences(), t.rates(), tables.scheme(), 6);
    const SharpCut input = cut_along_sharp_edges(mesh, links, sharpness, edge_and_corner);
    check_loop_vertices(input, input.cut ? link_polygons(input.mesh, true) : links, links,
                        no_surface_vertices(no_boundary_surface, mesh, links, sharpness, input), tables.scheme(), t, valences);
    valences.finish();
  }
  const bool sqrt3 = t.refinement() == TriangleRefinement::Sqrt3;
  out.mesh = mesh;
  // One whole-mesh step; Loop's with OpenSubdiv's creasing where there are sharp
  // features (sqrt(3) has none: it refuses them above).
  auto step_once = [&] {
    TriangleStep step = sqrt3 ? sqrt3_double_step(topo, t) : loop_step(topo, t, boundary ? &*boundary : nullptr);
    if (!sharpness.smooth()) {
      // On a mesh with boundaries its boundary edges count as infinitely sharp (OpenSubdiv).
      sharpness = sharpen_step(out.mesh, sharpness, crease, loop_step_edge_points(out.mesh, step.mesh), step.steps.front(),
                               edge_and_corner && out.boundary);
      ++out.crease_steps;
    }
    if (sqrt3) out.hierarchy.add_uniform(9, 3);
    else out.hierarchy.add_uniform(4, 2);
    for (RefinementStep& s : step.steps) out.refinement.add(std::move(s));
    out.mesh = std::move(step.mesh);
    ++out.steps;
    topo = TriangleTopology(out.mesh, out.boundary);
  };
  // Semi-sharp features decay by at least 1 a step: steps until none is left
  // (infinitely sharp ones are boundaries of the cut mesh: family/sharp_cut.hpp).
  if (!local)
    while (sharpness.has_semi_sharp()) step_once();
  const int before_isolation = out.steps;
  auto patch_mesh = std::make_unique<PatchMesh>(out.mesh, topo, sharpness, edge_and_corner, no_boundary_surface);
  while (!gather_patches(patch_mesh->topology(topo), t, out.patches, out.phantoms, patch_mesh->no_surface, patch_mesh->rules)) {
    if (out.steps - before_isolation == limits::kMaxRefinementSteps)
      throw MeshError("extraordinary vertices are still too close " +
                      std::string(patch_mesh->cut ? "to each other or to a boundary or crease "
                                                  : out.boundary ? "to each other or to the boundary " : "") + "after " +
                      std::to_string(limits::kMaxRefinementSteps) + " " + (sqrt3 ? "double sqrt(3) steps" : "subdivision steps"));
    step_once();
    patch_mesh = std::make_unique<PatchMesh>(out.mesh, topo, sharpness, edge_and_corner, no_boundary_surface);
  }
  // The cut mesh's extra vertices (copies of those on creases), then the
  // phantoms, are prepared points after the mesh's own.
  if (patch_mesh->cut && patch_mesh->cut->cut) {
    out.refinement.add(append_rows(out.mesh.vertex_count, copy_rows(*patch_mesh->cut, out.mesh.vertex_count)));
  }
  if (!out.phantoms.rows.empty()) out.refinement.add(append_rows(out.phantoms.first, out.phantoms.rows));
  if (local) refine_round_features(out, t, sharpness, crease, edge_and_corner && out.boundary, no_boundary_surface);
  return out;
}

void TriangleFamily::refine_round_features(Prepared& out, const TriangleTables& t, const LevelSharpness& sharpness,
                                           const CurveCreaseRule& crease, bool boundary_corners, bool no_boundary_surface) {
  if (!sharpness.has_semi_sharp()) return;  // the isolation steps took it all
  // Loop steps on each region, its border under the boundary rules (the points next to it are not used).
  const BoundaryRules rules{crease.centre, crease.neighbour, boundary_corners};
  const RegionStepper step = [&](const Connectivity& region) {
    TriangleStep s = loop_step(TriangleTopology(region, true), t, &rules);
    RegionStep r;
    r.edge_points = loop_step_edge_points(region, s.mesh);
    r.step = std::move(s.steps.front());
    r.mesh = std::move(s.mesh);
    return r;
  };
  SemiSharpRefinement r = refine_round_semi_sharp(out.mesh, sharpness, step, crease, boundary_corners);
  out.feature_levels = static_cast<int>(r.levels.size());
  out.feature_faces = r.faces() - out.mesh.face_count();
  const auto gather = [&](const SharpCut& cut, const std::vector<char>& no_surface, const std::vector<char>& exact,
                          std::vector<TrianglePatch>& patches) {
    const TriangleTopology topo(cut.mesh, true);
    PhantomPoints phantoms;
    phantoms.first = cut.mesh.vertex_count;
    const bool cones = has_cones(cut.rule);
    for (std::size_t f = 0; f < patches.size(); ++f) {
      if (!exact[f]) continue;
      std::optional<TrianglePatch> p = face_patch(topo, f, t, phantoms, no_surface, cut.rule, cones);
      // Children of isolated faces are isolated: a node without its patch is a mistake here.
      if (!p) throw MeshError("internal: a face refined round a semi-sharp feature has no patch");
      patches[f] = std::move(*p);
    }
    return std::move(phantoms.rows);
  };
  hang_levels(r, boundary_corners, no_boundary_surface, out.refinement, out.tree, out.patches, gather);
}

TriangleFamily::TriangleFamily(std::shared_ptr<const Tables> tables, const Connectivity& mesh, const MeshFeatures& sharp)
    : TriangleFamily(tables, prepare(*tables, mesh, sharp)) {}

TriangleFamily::TriangleFamily(std::shared_ptr<const Tables> tables, Prepared prepared)
    : holder_(std::move(tables)),
      tables_(holder_->triangle()),
      steps_(prepared.steps),
      crease_steps_(prepared.crease_steps),
      topology_(prepared.mesh, prepared.boundary),
      patches_(std::move(prepared.patches)),
      tree_(std::move(prepared.tree)),
      feature_levels_(prepared.feature_levels),
      feature_faces_(prepared.feature_faces) {
  if (tables_.has_descent()) descent_.emplace(tables_);
  if (tables_.polynomial_degree() > 0) derivative_rows_.emplace(tables_.polynomial_degree(), tables_.polynomial(), tables_.layout(6).size());
  refinement_ = std::move(prepared.refinement);
  hierarchy_ = std::move(prepared.hierarchy);
  prepared_ = std::move(prepared.mesh);
}

template <class P>
std::pair<std::size_t, std::array<P, 2>> TriangleFamily::patch_parameter(std::size_t face, P u, P v) const {
  const auto [pf, p] = locate_any(face, u, v);
  // Into the patch's own coordinates (TrianglePatch::to_patch).
  std::array<P, 2> q = p;
  const P w = subtract(subtract(integer<P>(1), p[0]), p[1]);
  if (patches_[pf].rotation == 1) q = {p[1], w};
  else if (patches_[pf].rotation == 2) q = {w, p[0]};
  return {pf, q};
}

template <class P>
Approximation TriangleFamily::descend(std::size_t face, P u, P v, double tolerance, const Point* prepared) const {
  const TrianglePatchDescent& descent = checked_descent();
  const auto [pf, q] = patch_parameter(face, u, v);
  const TrianglePatch& patch = patches_[pf];
  std::vector<Point> points = gather_points(patch.points, prepared);
  return descent.evaluate(patch.valence, patch.region, points, q[0], q[1], tolerance);
}

template <class P>
bool TriangleFamily::descent_stencil(std::size_t face, P u, P v, PatchStencil& out) const {
  if (!descent_) return false;
  try {
    const auto located = patch_parameter(face, u, v);  // not a structured binding: lambdas capture it (clang 14)
    const std::size_t pf = located.first;
    const std::array<P, 2> q = located.second;
    const TrianglePatch& patch = patches_[pf];
    return linear_stencil(pf, patch.points, [&](std::vector<Point>& unit) { return descent_->evaluate(patch.valence, patch.region, unit, q[0], q[1], 0.0); }, out);
  } catch (const ParameterOverflow&) {  // beyond 64-bit fractions: no exact row
    return false;
  }
}

bool TriangleFamily::real_stencil(std::size_t face, double u, double v, PatchStencil& out) const {
  return descent_stencil(face, u, v, out);
}

const TrianglePatchDescent& TriangleFamily::checked_descent() const {
  if (!descent_)
    throw EvaluationError("these triangle tables hold no patch subdivision (version 2 .sgt): evaluation at parameters "
                          "they do not hold needs tables from this stencilgen");
  return *descent_;
}

Approximation TriangleFamily::evaluate(std::size_t face, const ExactParameter& at, double tolerance, const Point* prepared) const {
  try {
    PatchStencil s;
    if (held_stencil(face, at, s)) {  // held by the tables: no descent needed (nor patch subdivision data)
      Approximation out;
      out.point = stencil_sum(s.weights, s.points, s.size, prepared);
      return out;
    }
    return descend(face, at.u, at.v, tolerance, prepared);
  } catch (const ParameterOverflow&) {  // beyond 64-bit fractions (finding the face's part too): the nearest double
    Approximation a = descend(face, at.u.to_double(), at.v.to_double(), tolerance, prepared);
    a.exact = false;
    return a;
  }
}

Approximation TriangleFamily::evaluate(std::size_t face, double u, double v, double tolerance, const Point* prepared) const {
  // A double is an exact dyadic fraction: evaluated exactly where the tables reach it.
  const auto fu = exact_fraction(u), fv = exact_fraction(v);
  if (fu && fv) return evaluate(face, ExactParameter{*fu, *fv}, tolerance, prepared);
  return descend(face, u, v, tolerance, prepared);
}

Derivatives TriangleFamily::derivatives(std::size_t face, double u, double v, const Point* prepared) const {
  if (tables_.polynomial_degree() == 0) {  // sqrt(3): exact stencils at the grid points the tables hold
    const auto fu = exact_fraction(u), fv = exact_fraction(v);
    const std::string refusal = "this scheme's regular patch is not a polynomial (sqrt(3)): derivatives only at exact "
                                "parameters on its tables' grids (k/n of a stored rate n, given as a fraction such as "
                                "1/3), and (" + std::to_string(u) + ", " + std::to_string(v) + ") is not one";
    if (!fu || !fv) throw EvaluationError(refusal);
    try {
      return derivatives(face, ExactParameter{*fu, *fv}, prepared);
    } catch (const ParameterOverflow&) {  // a binary fraction the descent cannot follow in 64 bits
      throw EvaluationError(refusal);
    } catch (const OffGridDerivative&) {
      throw EvaluationError(refusal);
    }
  }
  return second_derivatives(face, u, v, prepared);  // the regular cell's quartic gives both at once
}

SecondDerivatives TriangleFamily::second_derivatives(std::size_t face, double u, double v, const Point* prepared) const {
  const TrianglePatchDescent& descent = checked_descent();
  const auto [pf, q] = patch_parameter(face, Dual{u, 1, 0}, Dual{v, 0, 1});
  const TrianglePatch& patch = patches_[pf];
  std::vector<Point> points = gather_points(patch.points, prepared);
  return descent.second_derivatives(patch.valence, patch.region, points, q[0], q[1]);
}

SecondDerivatives TriangleFamily::second_derivatives(std::size_t face, const ExactParameter& at, const Point* prepared) const {
  return second_derivatives(face, at.u.to_double(), at.v.to_double(), prepared);
}

Point TriangleFamily::normal(std::size_t face, double u, double v, const Point* prepared) const {
  const auto [pf, q] = patch_parameter(face, Dual{u, 1, 0}, Dual{v, 0, 1});
  const TrianglePatch& patch = patches_[pf];
  if (patch.valence == 6 || patch.region != 0 || q[0].value != 0 || q[1].value != 0)
    return derivatives(face, u, v, prepared).normal();
  return vertex_normal(patch, q[0].du * q[1].dv - q[0].dv * q[1].du, prepared);
}

Point TriangleFamily::vertex_normal(const TrianglePatch& patch, double det, const Point* prepared) const {
  // The extraordinary vertex: t_u.P x t_v.P, turned if the map from the face
  // to the patch turns the orientation (det: the Jacobian's determinant).
  const std::vector<double>* tu = tables_.tangent_u(patch.valence);
  const std::vector<double>* tv = tables_.tangent_v(patch.valence);
  if ((!tu || !tv) && TriangleTables::is_sector_code(patch.valence)) {
    const SectorKey& s = tables_.sector(patch.valence);
    throw EvaluationError(s.rule == SectorRule::Corner ? "a corner has no tangent plane, so there is no normal at it"
                          : s.rule == SectorRule::Cone ? "a cone point has no tangent plane, so there is no normal at it"
                          : s.rule == SectorRule::Dart
                              ? "the spectrum of Loop's subdivision at a dart of valence " + std::to_string(s.faces) +
                                    " (the end of an infinitely sharp crease) gives no tangent plane, so there is no normal at it"
                              : "Loop's boundary rules give no tangent plane at a boundary vertex in " + std::to_string(s.faces) +
                                    " faces that the spectrum of its subdivision shows (docs/runtime.md), so there is no "
                                    "normal at it");
  }
  if (!tu || !tv || tu->size() != patch.points.size())
    throw EvaluationError("the tables hold no tangent stencils at the " + kind_name(patch.valence) +
                          ", so there is no normal at the extraordinary vertex (.sgt tables from before version 4: "
                          "regenerate them)");
  Derivatives tangents;
  for (std::size_t h = 0; h < patch.points.size(); ++h) {
    const Point& p = prepared[patch.points[h]];
    for (std::size_t c = 0; c < 3; ++c) tangents.du[c] += (*tu)[h] * p[c], tangents.dv[c] += (*tv)[h] * p[c];
  }
  Point n = tangents.normal();
  if (det < 0)
    for (double& x : n) x = -x;
  return n;
}

Point TriangleFamily::normal(std::size_t face, const ExactParameter& at, const Point* prepared) const {
  if (tables_.polynomial_degree() > 0) return normal(face, at.u.to_double(), at.v.to_double(), prepared);
  const auto [pf, q] = patch_parameter(face, ExactDual{at.u, 1, 0}, ExactDual{at.v, 0, 1});
  const TrianglePatch& patch = patches_[pf];
  if (patch.valence == 6 || patch.region != 0 || q[0].value.num != 0 || q[1].value.num != 0)
    return derivatives(face, at, prepared).normal();
  return vertex_normal(patch, q[0].du * q[1].dv - q[0].dv * q[1].du, prepared);
}

Derivatives TriangleFamily::derivatives(std::size_t face, const ExactParameter& at, const Point* prepared) const {
  // Loop: the regular patch's polynomial is evaluated in doubles either way.
  if (tables_.polynomial_degree() > 0) return derivatives(face, at.u.to_double(), at.v.to_double(), prepared);
  const TrianglePatchDescent& descent = checked_descent();
  const auto [pf, q] = patch_parameter(face, ExactDual{at.u, 1, 0}, ExactDual{at.v, 0, 1});
  const TrianglePatch& patch = patches_[pf];
  std::vector<Point> points = gather_points(patch.points, prepared);
  return descent.derivatives(patch.valence, patch.region, points, q[0], q[1]);
}

std::string TriangleFamily::preparation() const {
  return std::to_string(steps_) + (sqrt3() ? " double sqrt(3) step" : " subdivision step") + (steps_ == 1 ? "" : "s") +
         (crease_steps_ > 0 ? " (" + std::to_string(crease_steps_) + " of them with the creases' sharp rules)" : "") +
         (feature_levels_ > 0 ? ", then " + std::to_string(feature_levels_) + " level" + (feature_levels_ == 1 ? "" : "s") +
                                    " refined round the semi-sharp features (" + std::to_string(feature_faces_) + " faces)"
                              : "");
}

FaceDomain TriangleFamily::domain(std::size_t) const { return FaceDomain::of(SchemeFamily::Triangle, 3); }

template <class P>
std::pair<std::size_t, std::array<P, 2>> TriangleFamily::locate_any(std::size_t face, P u, P v) const {
  std::array<P, 2> p{u, v};
  for (const FaceHierarchy::Level& level : hierarchy_.levels) {
    const auto [c, child] = level.scale == 3 ? ternary_child(p[0], p[1]) : loop_child(p[0], p[1]);
    face = level.child_offsets[face] + static_cast<std::size_t>(c);
    p = child;
  }
  while (refined(face)) {  // down the levels refined round semi-sharp features, by the same Loop split
    const auto [c, child] = loop_child(p[0], p[1]);
    face = tree_.child(face, c);
    p = child;
  }
  return {face, p};
}

std::pair<std::size_t, ExactParameter> TriangleFamily::locate(std::size_t face, const ExactParameter& at) const {
  const auto [prepared, p] = locate_any(face, at.u, at.v);
  return {prepared, {p[0], p[1]}};
}

std::pair<std::size_t, std::array<double, 2>> TriangleFamily::locate(std::size_t face, double u, double v) const {
  return locate_any(face, u, v);
}

bool TriangleFamily::stencil(std::size_t face, const ExactParameter& at, PatchStencil& out) const {
  return held_stencil(face, at, out) || descent_stencil(face, at.u, at.v, out);
}

bool TriangleFamily::held_stencil(std::size_t face, const ExactParameter& at, PatchStencil& out) const {
  const auto [prepared, p] = locate(face, at);
  const TrianglePatch& patch = patches_[prepared];
  const ExactParameter q = patch.to_patch(p);
  // The smallest stored rate n whose grid 1/(3n) holds both coordinates as a
  // node (both = 0 mod 3), an up centre (both 1) or a down centre (both 2).
  for (int n : tables_.rates()) {
    const std::int64_t g = 3 * static_cast<std::int64_t>(n);
    if (g % q.u.den != 0 || g % q.v.den != 0) continue;
    const std::int64_t a = q.u.num * (g / q.u.den), b = q.v.num * (g / q.v.den);
    if (a % 3 != b % 3) continue;
    out.face = prepared;
    out.points = patch.points.data();
    out.size = patch.points.size();
    out.weights = tables_.grid(patch.valence, n, patch.region).weights(static_cast<TriangleTables::GridPoint>(a % 3), a / 3, b / 3);
    return true;
  }
  return false;
}

}  // namespace stencil_runtime
