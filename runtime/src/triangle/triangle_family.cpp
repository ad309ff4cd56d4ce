#include "triangle_family.hpp"

#include <string>

#include "family/parameter_ops.hpp"
#include "triangle_steps.hpp"

namespace stencil_runtime {

struct TriangleFamily::Prepared {
  Refinement refinement;
  FaceHierarchy hierarchy;
  int steps = 0;
  Connectivity mesh;
  std::vector<TrianglePatch> patches;  // as the last isolation check found them
};

namespace {

// Every face's patch, or false when one cannot be gathered.
bool gather_patches(const TriangleTopology& topo, const TriangleTables& tables, std::vector<TrianglePatch>& patches) {
  patches.clear();
  patches.reserve(topo.faces());
  for (std::size_t f = 0; f < topo.faces(); ++f) {
    auto patch = find_triangle_patch(topo, f, tables);
    if (!patch) return false;
    patches.push_back(std::move(*patch));
  }
  return true;
}

// Child of a face split by a Loop step (loop_step) holding (u, v), and the parameter there.
std::pair<int, ExactParameter> loop_child(const ExactParameter& p) {
  // Barycentric coordinates times 2: (k, a, b) on corners 0, 1, 2. The child at
  // corner c holds the points where corner c's weight is at least 1/2.
  const Fraction one{1, 1};
  const Fraction a = multiply(p.u, 2), b = multiply(p.v, 2);
  const Fraction k = subtract(subtract(Fraction{2, 1}, a), b);
  if (compare(k, one) >= 0) return {0, {a, b}};
  if (compare(a, one) >= 0) return {1, {b, k}};
  if (compare(b, one) >= 0) return {2, {k, a}};
  return {3, {subtract(one, k), subtract(one, a)}};  // middle child: corners at the midpoints of edges 0, 1, 2
}

// Cell of the 1-to-9 split (ternary_cells) holding (u, v), and the parameter there.
std::pair<int, ExactParameter> ternary_child(const ExactParameter& p) {
  const Fraction x = multiply(p.u, 3), y = multiply(p.v, 3), zero{0, 1}, one{1, 1};
  int c = 0;
  for (const TernaryCell& cell : ternary_cells()) {
    ExactParameter q;
    if (cell.down) q = {subtract(add(x, y), Fraction{cell.a + cell.b + 1, 1}), subtract(Fraction{cell.a + 1, 1}, x)};
    else q = {subtract(x, Fraction{cell.a, 1}), subtract(y, Fraction{cell.b, 1})};
    if (compare(q.u, zero) >= 0 && compare(q.v, zero) >= 0 && compare(add(q.u, q.v), one) <= 0) return {c, q};
    ++c;
  }
  throw EvaluationError("parameter " + p.str() + " lies outside the triangle");
}

}  // namespace

TriangleFamily::Prepared TriangleFamily::prepare(const Tables& tables, const Connectivity& mesh) {
  const TriangleTables& t = tables.triangle();
  TriangleFamily::Prepared out;
  out.refinement = Refinement(mesh.vertex_count);
  out.hierarchy.original_faces = mesh.face_count();
  TriangleTopology topo(mesh);  // a closed manifold of triangles (names the face, edge or vertex)
  ValenceCheck valences(tables.valences(), t.rates(), tables.scheme(), 6);
  for (std::size_t v = 0; v < topo.vertices(); ++v)
    valences.add_lazy(topo.valence(static_cast<int>(v)), [&] { return "vertex " + std::to_string(v); });
  valences.finish();
  const bool sqrt3 = t.refinement() == TriangleRefinement::Sqrt3;
  out.mesh = mesh;
  while (!gather_patches(topo, t, out.patches)) {
    if (out.steps == limits::kMaxRefinementSteps)
      throw MeshError("extraordinary vertices are still too close after " + std::to_string(limits::kMaxRefinementSteps) + " " +
                      (sqrt3 ? "double sqrt(3) steps" : "subdivision steps"));
    TriangleStep step = sqrt3 ? sqrt3_double_step(topo, t) : loop_step(topo, t);
    if (sqrt3) out.hierarchy.add_uniform(9, 3);
    else out.hierarchy.add_uniform(4, 2);
    for (RefinementStep& s : step.steps) out.refinement.add(std::move(s));
    out.mesh = std::move(step.mesh);
    ++out.steps;
    topo = TriangleTopology(out.mesh);
  }
  return out;
}


TriangleFamily::TriangleFamily(std::shared_ptr<const Tables> tables, const Connectivity& mesh)
    : TriangleFamily(tables, prepare(*tables, mesh)) {}

TriangleFamily::TriangleFamily(std::shared_ptr<const Tables> tables, Prepared prepared)
    : holder_(std::move(tables)),
      tables_(holder_->triangle()),
      steps_(prepared.steps),
      topology_(prepared.mesh),
      patches_(std::move(prepared.patches)) {
  refinement_ = std::move(prepared.refinement);
  hierarchy_ = std::move(prepared.hierarchy);
  prepared_ = std::move(prepared.mesh);
}

Approximation TriangleFamily::evaluate(std::size_t face, const ExactParameter& at, double, const Point* prepared) const {
  PatchStencil s;
  if (!stencil(face, at, s))
    throw EvaluationError("the parameter " + at.str() + " of face " + std::to_string(face) +
                          " is on no grid the tables hold, and triangle schemes are evaluated only where they do");
  Approximation out;
  for (std::size_t h = 0; h < s.size; ++h)
    for (int k = 0; k < 3; ++k) out.point[static_cast<std::size_t>(k)] += s.weights[h] * prepared[s.points[h]][static_cast<std::size_t>(k)];
  return out;
}

Approximation TriangleFamily::evaluate(std::size_t face, double u, double v, double tolerance, const Point* prepared) const {
  const auto fu = exact_fraction(u), fv = exact_fraction(v);
  if (!fu || !fv)
    throw EvaluationError("triangle schemes are evaluated only at parameters their tables hold");
  return evaluate(face, ExactParameter{*fu, *fv}, tolerance, prepared);
}

std::string TriangleFamily::preparation() const {
  return std::to_string(steps_) + (sqrt3() ? " double sqrt(3) step" : " subdivision step") + (steps_ == 1 ? "" : "s");
}

FaceDomain TriangleFamily::domain(std::size_t) const { return FaceDomain::of(SchemeFamily::Triangle, 3); }

std::pair<std::size_t, ExactParameter> TriangleFamily::locate(std::size_t face, const ExactParameter& at) const {
  ExactParameter p = at;
  for (const FaceHierarchy::Level& level : hierarchy_.levels) {
    const auto [c, child] = level.scale == 3 ? ternary_child(p) : loop_child(p);
    face = level.child_offsets[face] + static_cast<std::size_t>(c);
    p = child;
  }
  return {face, p};
}

bool TriangleFamily::stencil(std::size_t face, const ExactParameter& at, PatchStencil& out) const {
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
