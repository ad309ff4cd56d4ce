#include "stencil_runtime/surface_topology.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <numeric>
#include <set>
#include <string>
#include <type_traits>

#include "exact_stencil.hpp"

#include "family/family.hpp"
#include "family/sharp_cut.hpp"
#include "mesh/manifold_input.hpp"
#include "mesh/polygon_links.hpp"
#include "mesh/sharpness.hpp"
#include "quad/quad_family.hpp"
#include "stencil_runtime/limits.hpp"
#include "triangle/triangle_family.hpp"

namespace stencil_runtime {

namespace {

// holes_: 1 for a face tagged `hole`, this for one that `none` takes the surface from.
constexpr char kNoBoundarySurface = 2;

// Appended to every topology error: the library numbers from 0, OBJ files from 1.
constexpr const char* kNumbering =
    " (faces and vertices are numbered from 0 in file order; an OBJ file's vertex k is vertex k-1 here)";

}  // namespace

SurfaceTopology::SurfaceTopology() = default;
SurfaceTopology::~SurfaceTopology() = default;

std::shared_ptr<const SurfaceTopology> SurfaceTopology::create(std::shared_ptr<const Tables> tables, std::size_t vertex_count,
                                                               std::vector<int> face_sizes, std::vector<int> face_vertices,
                                                               const std::vector<int>& holes, const MeshFeatures& features) {
  if (!tables) throw EvaluationError("SurfaceTopology::create needs tables");
  if (face_sizes.empty()) throw MeshError("the mesh has no faces");
  if (vertex_count > limits::kMaxMeshElements || face_sizes.size() > limits::kMaxMeshElements)
    throw MeshError("the mesh has " + std::to_string(vertex_count) + " vertices and " + std::to_string(face_sizes.size()) +
                    " faces; the runtime supports up to " + std::to_string(limits::kMaxMeshElements) + " of each");
  for (std::size_t f = 0; f < face_sizes.size(); ++f)
    if (face_sizes[f] < 3 || face_sizes[f] > limits::kMaxFaceSize)
      throw MeshError("face " + std::to_string(f) + " has " + std::to_string(face_sizes[f]) + " vertices (faces have 3.." +
                      std::to_string(limits::kMaxFaceSize) + ")" + kNumbering);
  if (features.boundary != BoundaryInterpolation::None && features.boundary != BoundaryInterpolation::EdgeOnly &&
      features.boundary != BoundaryInterpolation::EdgeAndCorner)
    throw MeshError("unknown boundary interpolation " + std::to_string(static_cast<int>(features.boundary)) +
                    " (none, edge-only or edge-and-corner)");
  std::vector<char> hole_flags;
  if (!holes.empty()) {
    hole_flags.assign(face_sizes.size(), 0);
    for (int f : holes) {
      if (f < 0 || static_cast<std::size_t>(f) >= face_sizes.size())
        throw MeshError("hole face " + std::to_string(f) + " does not exist (the mesh has " +
                        std::to_string(face_sizes.size()) + " faces, numbered from 0)");
      hole_flags[static_cast<std::size_t>(f)] = 1;
    }
    if (std::find(hole_flags.begin(), hole_flags.end(), 0) == hole_flags.end())
      throw MeshError("every face is a hole: the mesh has no surface");
  }
  std::shared_ptr<SurfaceTopology> t(new SurfaceTopology());
  t->holes_ = std::move(hole_flags);
  t->tables_ = std::move(tables);
  t->vertex_count_ = vertex_count;
  t->face_sizes_ = std::move(face_sizes);
  t->face_vertices_ = std::move(face_vertices);
  // Vertices in no face left out, non-manifold vertices split into their fans
  // (mesh/manifold_input.hpp); the tags are checked on the mesh as given first.
  Connectivity mesh{t->vertex_count_, t->face_sizes_, t->face_vertices_};
  ManifoldInput input;
  try {
    if (!features.edges.empty() || !features.vertices.empty()) LevelSharpness::of(mesh, features, true);
    input = make_manifold(mesh, features);
  } catch (const MeshError& e) {
    throw MeshError(std::string(e.what()) + kNumbering);
  }
  // A non-manifold vertex or edge becomes corners and sharp edges (as in
  // OpenSubdiv), which sqrt(3) has no rule for: said as such, not as the
  // creases the user never tagged.
  if (input.changed && t->tables_->family() == SchemeFamily::Triangle &&
      t->tables_->triangle().refinement() == TriangleRefinement::Sqrt3) {
    std::vector<char> seen(t->vertex_count_, 0);
    for (const int v : input.origin)
      if (seen[static_cast<std::size_t>(v)]++)
        throw MeshError("vertex " + std::to_string(v) +
                        " is non-manifold (its faces form more than one fan, or an edge there is in more than two faces "
                        "or used twice in one direction): it is split into corners and sharp edges, as OpenSubdiv does, "
                        "and the scheme " + t->tables_->scheme() + " refines by sqrt(3), which has no corner or crease rule" +
                        kNumbering);
  }
  if (input.changed) {
    mesh.vertex_count = input.origin.size();
    mesh.face_vertices = std::move(input.face_vertices);
  }
  const MeshFeatures& tags = input.changed ? input.features : features;
  std::unique_ptr<Family> family;
  try {
    if (t->tables_->family() == SchemeFamily::Quad) {
      family = std::make_unique<QuadFamily>(t->tables_, mesh, tags);
    } else {
      family = std::make_unique<TriangleFamily>(t->tables_, mesh, tags);
    }
  } catch (const MeshError& e) {
    throw MeshError((input.changed ? name_control_vertices(e.what(), input.origin) : std::string(e.what())) + kNumbering);
  }
  if (input.changed) family->gather_from(t->vertex_count_, input.origin);
  t->family_ = std::move(family);
  if (features.boundary == BoundaryInterpolation::None && t->family_->has_boundary()) {
    // OpenSubdiv's `none`: the faces at a boundary vertex keep their part in
    // the subdivision but have no surface, as holes, unless every boundary
    // edge there is tagged infinitely sharp (family/sharp_cut.hpp). A
    // non-manifold vertex counts when any of its fans does.
    const std::vector<char> own = surfaceless_vertices(mesh, link_polygons(mesh, true), LevelSharpness::of(mesh, tags, true));
    std::vector<char> surfaceless(t->vertex_count_, 0);
    for (std::size_t v = 0; v < mesh.vertex_count; ++v)
      if (own[v]) surfaceless[static_cast<std::size_t>(input.changed ? input.origin[v] : static_cast<int>(v))] = 1;
    if (t->holes_.empty()) t->holes_.assign(t->face_sizes_.size(), 0);
    std::size_t offset = 0;
    for (std::size_t f = 0; f < t->face_sizes_.size(); ++f) {
      for (int c = 0; c < t->face_sizes_[f]; ++c)
        if (surfaceless[static_cast<std::size_t>(t->face_vertices_[offset + static_cast<std::size_t>(c)])] && !t->holes_[f])
          t->holes_[f] = kNoBoundarySurface;
      offset += static_cast<std::size_t>(t->face_sizes_[f]);
    }
    if (std::find(t->holes_.begin(), t->holes_.end(), 0) == t->holes_.end())
      throw MeshError("every face has a vertex on the boundary (whose boundary edges are not all tagged infinitely sharp): with the boundary interpolation `none` the mesh has no surface");
  }
  return t;
}

bool SurfaceTopology::same_connectivity(std::size_t vertex_count, const std::vector<int>& face_sizes,
                                        const std::vector<int>& face_vertices) const {
  return vertex_count == vertex_count_ && face_sizes == face_sizes_ && face_vertices == face_vertices_;
}

FaceDomain SurfaceTopology::domain(std::size_t face) const {
  if (face >= face_count())
    throw EvaluationError("face " + std::to_string(face) + " does not exist (the mesh has " + std::to_string(face_count()) +
                          " faces, numbered from 0)");
  if (is_hole(face))
    throw EvaluationError("face " + std::to_string(face) +
                          (holes_[face] == kNoBoundarySurface
                               ? " has a vertex on the boundary, and under boundary interpolation `none` such faces have no surface"
                               : " is a hole (tagged `hole` in the mesh): it has no surface"));
  return family_->domain(face);
}

std::vector<char> SurfaceTopology::prepared_holes() const {
  if (holes_.empty()) return {};
  std::vector<char> out(family_->hierarchy().prepared_faces(), 0);
  for (std::size_t f = 0; f < holes_.size(); ++f)
    if (holes_[f]) {
      const auto [first, last] = family_->hierarchy().prepared_range(f);
      std::fill(out.begin() + static_cast<std::ptrdiff_t>(first), out.begin() + static_cast<std::ptrdiff_t>(last), 1);
    }
  return out;
}

std::string SurfaceTopology::preparation() const { return family_->preparation(); }
int SurfaceTopology::refinement_steps() const { return family_->refinement_steps(); }
std::size_t SurfaceTopology::prepared_face_count() const { return family_->hierarchy().prepared_faces(); }
bool SurfaceTopology::has_boundary() const { return family_->has_boundary(); }

std::size_t SurfaceTopology::prepared_vertex_count() const { return family_->refinement().prepared_vertices(); }

namespace {

// Why the tables do not hold an exact parameter, and what would.
EvaluationError not_held(const SurfaceTopology& topology, std::size_t face, const ExactParameter& at) {
  const std::string what = "the parameter " + at.str() + " of face " + std::to_string(face) +
                           " is on no grid the tables hold (rates " + compact_list(topology.tables().rates(), true) + ")";
  const std::int64_t g = std::gcd(at.u.den, at.v.den);
  const std::int64_t l = at.u.den / g;
  if (l > limits::kMaxRate / at.v.den)
    return EvaluationError(what + "; its denominators need a rate above " + std::to_string(limits::kMaxRate) +
                           ", so no table holds it exactly: evaluate it as a decimal within a tolerance");
  const std::int64_t rate = l * at.v.den;
  return EvaluationError(what + "; tables with rate " + std::to_string(rate) + " make it exact: stencilgen --scheme " +
                         topology.tables().scheme() + " --valence <valences> --n " + compact_list(topology.tables().rates(), true) +
                         "," + std::to_string(rate) + "-" + std::to_string(rate) + " --out <dir>");
}

// The stencil at an exact parameter, checked, or an EvaluationError that says why not.
PatchStencil checked_stencil(const SurfaceTopology& topology, std::size_t face, const ExactParameter& at) {
  const FaceDomain domain = topology.domain(face);
  if (!domain.contains(at))
    throw EvaluationError(domain.outside(face, at));
  PatchStencil s;
  try {
    if (!topology.family().stencil(face, at, s)) throw not_held(topology, face, at);
  } catch (const ParameterOverflow&) {
    throw EvaluationError("the parameter " + at.str() + " of face " + std::to_string(face) +
                          " needs fractions beyond 64 bits on the way to a patch the tables hold, so it has no exact "
                          "row: evaluate it as a decimal within a tolerance");
  }
  return s;
}

}  // namespace

PatchStencil exact_stencil(const SurfaceTopology& topology, std::size_t face, const ExactParameter& at) {
  return checked_stencil(topology, face, at);
}

namespace {

// The stencil at a real parameter, checked, or an EvaluationError that says why not.
PatchStencil checked_stencil(const SurfaceTopology& topology, std::size_t face, double u, double v) {
  const FaceDomain domain = topology.domain(face);
  if (!domain.contains(u, v)) throw EvaluationError(domain.outside(face, u, v));
  PatchStencil s;
  if (!topology.family().stencil(face, u, v, s))
    throw EvaluationError("the limit point at " + parameter_text(u, v) + " of face " + std::to_string(face) +
                          " has no exact row: the tables do not hold the parameter, and the patch's descent reaches "
                          "neither a grid they hold nor a polynomial regular patch (a scheme whose regular patches are "
                          "not polynomial, or a parameter finer than the descent follows); evaluate it within a "
                          "tolerance (Surface::evaluate) instead");
  return s;
}

// Each row: the patch stencil over prepared vertices, folded through R.
template <class SampleT>
StencilRows rows_of(const SurfaceTopology& topology, const Family& family, const std::vector<SampleT>& samples) {
  std::vector<SparseEntries> rows(samples.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples.size(), 64), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t k = r.begin(); k != r.end(); ++k) {
      PatchStencil s;
      if constexpr (std::is_same_v<SampleT, Sample>) s = checked_stencil(topology, samples[k].face, samples[k].at);
      else s = checked_stencil(topology, samples[k].face, samples[k].u, samples[k].v);
      SparseEntries& row = rows[k];
      row.reserve(s.size);
      for (std::size_t h = 0; h < s.size; ++h) row.emplace_back(static_cast<std::uint32_t>(s.points[h]), s.weights[h]);
      family.refinement().fold(row);
    }
  });
  StencilRows out;
  out.columns = topology.vertex_count();
  for (const SparseEntries& row : rows) {
    for (const auto& [c, w] : row) {
      out.vertices.push_back(c);
      out.weights.push_back(w);
    }
    out.offsets.push_back(out.vertices.size());
  }
  return out;
}

}  // namespace

StencilRows SurfaceTopology::stencil(std::size_t face, const ExactParameter& at) const {
  return stencils(std::vector<Sample>{{face, at}});
}
StencilRows SurfaceTopology::stencils(const std::vector<Sample>& samples) const { return rows_of(*this, *family_, samples); }
StencilRows SurfaceTopology::stencil(std::size_t face, double u, double v) const {
  return stencils(std::vector<RealSample>{{face, u, v}});
}
StencilRows SurfaceTopology::stencils(const std::vector<RealSample>& samples) const { return rows_of(*this, *family_, samples); }

std::vector<Point> StencilRows::apply(const std::vector<Point>& control) const {
  if (control.size() != columns)
    throw EvaluationError("the rows are over " + std::to_string(columns) + " control vertices; " +
                          std::to_string(control.size()) + " positions given");
  std::vector<Point> out(rows());
  for (std::size_t r = 0; r < rows(); ++r) {
    Point p{0, 0, 0};
    for (std::size_t e = offsets[r]; e != offsets[r + 1]; ++e)
      for (int k = 0; k < 3; ++k) p[static_cast<std::size_t>(k)] += weights[e] * control[vertices[e]][static_cast<std::size_t>(k)];
    out[r] = p;
  }
  return out;
}

}  // namespace stencil_runtime
