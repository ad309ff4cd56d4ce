#include <algorithm>
#include <cmath>
#include <string>

#include "family/family.hpp"
#include "stencil_runtime/limits.hpp"
#include "stencil_runtime/tessellation.hpp"

namespace stencil_runtime {

struct TessellationPlan::Impl {
  TessellationLayout layout;
  int largest_wanted = 0;
  std::unique_ptr<detail::RangeRunner> run;
};

TessellationPlan::TessellationPlan(std::shared_ptr<const SurfaceTopology> topology, const std::vector<int>& rates,
                                   const TessellationOptions& options)
    : topology_(std::move(topology)), impl_(std::make_unique<Impl>()) {
  if (!topology_) throw EvaluationError("a TessellationPlan needs a topology");
  if (rates.size() != topology_->face_count())
    throw EvaluationError("need one rate per face: got " + std::to_string(rates.size()) + " for " +
                          std::to_string(topology_->face_count()) + " faces");
  for (std::size_t f = 0; f < rates.size(); ++f)
    if (rates[f] < 1 || rates[f] > limits::kMaxRate)
      throw EvaluationError("face " + std::to_string(f) + ": rate " + std::to_string(rates[f]) + " is outside 1.." +
                            std::to_string(limits::kMaxRate));
  if (options.threads < 0) throw EvaluationError("threads must be 0 (all cores) or positive");
  const Family& family = topology_->family();
  TessellationLayout& layout = impl_->layout;
  layout.rates = family.hierarchy().prepared_rates(rates);
  layout.holes = topology_->prepared_holes();
  std::size_t points = 0;
  for (int& r : layout.rates) {
    impl_->largest_wanted = std::max(impl_->largest_wanted, r);
    r = topology_->tables().rate_at_least(r);
    points += static_cast<std::size_t>(r) * static_cast<std::size_t>(r);
  }
  impl_->run = std::make_unique<detail::RangeRunner>(options.threads, points);
  family.plan(layout, *impl_->run);
}

TessellationPlan::~TessellationPlan() = default;
TessellationPlan::TessellationPlan(TessellationPlan&&) noexcept = default;
TessellationPlan& TessellationPlan::operator=(TessellationPlan&&) noexcept = default;

const TessellationPlan::Impl& TessellationPlan::planned() const {
  if (!impl_) throw EvaluationError("the tessellation plan was moved from: it holds no plan");
  return *impl_;
}

const SurfaceTopology& TessellationPlan::topology() const {
  planned();
  return *topology_;
}
const std::vector<int>& TessellationPlan::prepared_rates() const { return planned().layout.rates; }
int TessellationPlan::largest_wanted_rate() const { return planned().largest_wanted; }
std::size_t TessellationPlan::point_count() const { return planned().layout.point_offsets.back() + impl_->layout.rim.size(); }
const std::vector<std::array<int, 4>>& TessellationPlan::quads() const { return planned().layout.quads; }
const std::vector<std::array<int, 3>>& TessellationPlan::triangles() const { return planned().layout.triangles; }

namespace {

// The prepared positions of a surface of this plan's topology, checked, and
// the output array (`what`: "positions" or "normals") not null.
const Point* prepared_of(const Surface& surface, const SurfaceTopology* planned, const void* out, const char* what) {
  if (!out) throw EvaluationError(std::string("the tessellation's ") + what + " are to go to a null pointer");
  if (&surface.topology() != planned)
    throw EvaluationError("the surface has another topology than the one this tessellation was planned for");
  if (!surface.has_positions()) throw EvaluationError("the surface has no control positions yet (set_positions)");
  return surface.prepared_positions().data();
}

}  // namespace

namespace {

// The rim's points (round holes), after the faces'.
void rim_points(const Family& family, const TessellationLayout& layout, const detail::RangeRunner& run,
                const Point* prepared, std::array<float, 3>* positions) {
  std::array<float, 3>* rim = positions + layout.point_offsets.back();
  run(layout.rim.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t r = begin; r != end; ++r) {
      const RimNode& node = layout.rim[r];
      const Point p = family.edge_node(node.face, node.corner, node.t, layout.rates[node.face], prepared);
      rim[r] = {static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])};
    }
  });
}

// The rim's normals, after the faces' normals: a rim point where the surface
// has no tangent plane, such as a corner, takes the normal of the face point beside it.
void rim_normals(const Family& family, const TessellationLayout& layout, const detail::RangeRunner& run,
                 const Point* prepared, std::array<float, 3>* normals) {
  std::array<float, 3>* rim = normals + layout.point_offsets.back();
  run(layout.rim.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t r = begin; r != end; ++r) {
      const RimNode& node = layout.rim[r];
      const auto [x, y] = family.edge_node_parameter(node.face, node.corner, node.t, layout.rates[node.face]);
      const FaceParameterReal at = family.original(node.face, x, y);
      try {
        const Point n = family.normal(at.face, at.u, at.v, prepared);
        if (std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2])) {
          rim[r] = {static_cast<float>(n[0]), static_cast<float>(n[1]), static_cast<float>(n[2])};
          continue;
        }
      } catch (const EvaluationError&) {
      }
      rim[r] = normals[node.beside];
    }
  });
}

}  // namespace

void TessellationPlan::evaluate(const Surface& surface, std::array<float, 3>* positions) const {
  const TessellationLayout& layout = planned().layout;
  const Point* prepared = prepared_of(surface, topology_.get(), positions, "positions");
  const Family& family = topology_->family();
  (*impl_->run)(layout.rates.size(), [&](std::size_t begin, std::size_t end) {
    family.points(layout, begin, end, prepared, positions);
  });
  rim_points(family, layout, *impl_->run, prepared, positions);
}

void TessellationPlan::evaluate_normals(const Surface& surface, std::array<float, 3>* normals) const {
  const TessellationLayout& layout = planned().layout;
  const Point* prepared = prepared_of(surface, topology_.get(), normals, "normals");
  const Family& family = topology_->family();
  (*impl_->run)(layout.rates.size(), [&](std::size_t begin, std::size_t end) {
    family.normals(layout, begin, end, prepared, normals);
  });
  rim_normals(family, layout, *impl_->run, prepared, normals);
}

void TessellationPlan::evaluate(const Surface& surface, std::array<float, 3>* positions,
                                std::array<float, 3>* normals) const {
  if (!normals) return evaluate(surface, positions);
  const TessellationLayout& layout = planned().layout;
  const Point* prepared = prepared_of(surface, topology_.get(), positions, "positions");
  const Family& family = topology_->family();
  (*impl_->run)(layout.rates.size(), [&](std::size_t begin, std::size_t end) {
    family.points_and_normals(layout, begin, end, prepared, positions, normals);
  });
  rim_points(family, layout, *impl_->run, prepared, positions);
  rim_normals(family, layout, *impl_->run, prepared, normals);
}

PolygonSoup TessellationPlan::make_soup() const {
  PolygonSoup soup;
  soup.quads = planned().layout.quads;
  soup.triangles = impl_->layout.triangles;
  soup.positions.resize(point_count());
  return soup;
}

PolygonSoup tessellate(const Surface& surface, const std::vector<int>& rates, const TessellationOptions& options,
                       bool normals) {
  const TessellationPlan plan(surface.shared_topology(), rates, options);
  PolygonSoup soup = plan.make_soup();
  if (normals) soup.normals.resize(soup.positions.size());
  plan.evaluate(surface, soup.positions.data(), normals ? soup.normals.data() : nullptr);
  return soup;
}

}  // namespace stencil_runtime
