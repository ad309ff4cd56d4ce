#include "stencil_runtime/closest_point.hpp"

#include <embree3/rtcore.h>
#include <nanoflann.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <cstdio>
#include <chrono>
#include <cmath>
#include <numbers>
#include <string>

#include "distance/face_search.hpp"
#include "distance/point_ops.hpp"
#include "mesh/coordinates.hpp"
#include "stencil_runtime/derivatives.hpp"
#include "stencil_runtime/error.hpp"
#include "stencil_runtime/limits.hpp"

namespace stencil_runtime {

using namespace point_ops;

namespace {


// A float no smaller (or no larger) than the double: Embree's boxes and radii
// are floats, and must not shrink what they bound.
float float_up(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) >= x ? f : std::nextafter(f, INFINITY);
}
float float_down(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) <= x ? f : std::nextafter(f, -INFINITY);
}

// Exact limit points with the prepared face and patch parameter they are at:
// the seeds that give each query a first upper bound on its distance.
struct Seeds {
  std::vector<Point> points;
  std::vector<std::size_t> faces;
  std::vector<std::array<double, 2>> at;

  std::size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t k) const { return points[i][k]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};
using SeedTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Seeds>, Seeds, 3, std::size_t>;

// Patch parameters of the seeds: the centre, and half-way from it to each corner.
std::vector<std::array<double, 2>> seed_parameters(const SubDomain& patch) {
  const auto c = patch.centre();
  std::vector<std::array<double, 2>> out{c};
  for (int k = 0; k < patch.corners(); ++k) {
    const auto corner = patch.corner(k);
    out.push_back({0.5 * (c[0] + corner[0]), 0.5 * (c[1] + corner[1])});
  }
  return out;
}

struct EmbreeDevice {
  RTCDevice device = rtcNewDevice(nullptr);
  ~EmbreeDevice() {
    if (device) rtcReleaseDevice(device);
  }
};

}  // namespace

struct ClosestPointQuery::Impl {
  std::shared_ptr<const SurfaceTopology> topology;
  const Family* family = nullptr;
  ClosestPointOptions options;
  double tolerance = 0;
  std::vector<Point> prepared;
  std::vector<std::array<float, 6>> boxes;  // per prepared face: a box around its surface (control points', or the slab's)
  std::vector<AffineEnclosure> enclosures;     // per sub-patch kind (empty where none)
  std::vector<ConvexBound> convex;             // per sub-patch kind (empty where none)
  PreparedRoots roots;                         // per prepared face: its patch's slab and convexity data
  std::vector<signed char> orientation;      // +1 where patch (x, y) keeps the original face's orientation
  std::vector<char> holes;                   // per prepared face: part of a hole (no surface), or empty
  Seeds seeds;
  std::unique_ptr<SeedTree> seed_tree;
  EmbreeDevice device;
  RTCScene scene = nullptr;
  double build_seconds = 0;
  double seed_tolerance = 0;  // how far a seed may be from the surface point it stands for

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
  }

  void build(const Surface& surface);
  ClosestPoint find(const Point& q) const;
  Point outward(const FaceHit& hit, const Point& normal) const;
};

namespace {

struct QueryState {
  FaceSearch* search;
  Point q;
  const FaceHit* best;
  const std::vector<char>* holes;  // per prepared face, or empty
};

void face_bounds(const RTCBoundsFunctionArguments* args) {
  const auto& boxes = *static_cast<const std::vector<std::array<float, 6>>*>(args->geometryUserPtr);
  const auto& b = boxes[args->primID];
  args->bounds_o->lower_x = b[0], args->bounds_o->lower_y = b[1], args->bounds_o->lower_z = b[2];
  args->bounds_o->upper_x = b[3], args->bounds_o->upper_y = b[4], args->bounds_o->upper_z = b[5];
}

// Embree calls this for every face whose box the query sphere touches: it
// queues the face for the branch-and-bound (the radius is already the best
// upper bound, so it does not shrink here).
bool visit_face(RTCPointQueryFunctionArguments* args) {
  auto* state = static_cast<QueryState*>(args->userPtr);
  if (!state->holes->empty() && (*state->holes)[args->primID]) return false;  // a hole has no surface
  state->search->add(args->primID, state->q, *state->best);
  return false;
}

// The faces whose boxes a small sphere round a surface point touches (holes left out).
struct FacesNear {
  std::vector<unsigned> faces;
  const std::vector<char>* holes;
};
bool collect_face(RTCPointQueryFunctionArguments* args) {
  auto* state = static_cast<FacesNear*>(args->userPtr);
  if (state->holes->empty() || !(*state->holes)[args->primID]) state->faces.push_back(args->primID);
  return false;
}

// Whether patch parameter (x, y) lies on the border of the whole patch (the unit square or triangle).
bool on_patch_border(bool triangle, double x, double y) {
  constexpr double e = 1e-12;
  if (x <= e || y <= e) return true;
  return triangle ? x + y >= 1 - e : x >= 1 - e || y >= 1 - e;
}

// The angle at (x, y) of a patch's domain: that of the corner it is at, in
// space (between the two sides' tangents, du and dv along the patch), pi on a
// side, 2 pi inside.
double domain_angle(bool triangle, double x, double y, const Derivatives& d) {
  const SubDomain unit = SubDomain::unit(triangle);
  constexpr double e = 1e-9;
  for (int k = 0; k < unit.corners(); ++k) {
    const auto c = unit.corner(k), next = unit.corner((k + 1) % unit.corners()),
               previous = unit.corner((k + unit.corners() - 1) % unit.corners());
    if (std::fabs(x - c[0]) > e || std::fabs(y - c[1]) > e) continue;
    const auto along = [&](const std::array<double, 2>& to) {
      const double a = to[0] - c[0], b = to[1] - c[1];
      return Point{a * d.du[0] + b * d.dv[0], a * d.du[1] + b * d.dv[1], a * d.du[2] + b * d.dv[2]};
    };
    // Scaled: the angle does not change, and neither cross nor dot
    // underflows on a tiny mesh (tangents of 1e-90).
    const Point e1 = scaled_to_unit_max(along(next)), e2 = scaled_to_unit_max(along(previous));
    return std::atan2(length(cross(e1, e2)), dot(e1, e2));
  }
  return on_patch_border(triangle, x, y) ? std::numbers::pi : 2 * std::numbers::pi;
}

}  // namespace

// The direction that says which side of the surface a point is on when its
// nearest surface point is the hit's: the normal there, unless the point is
// on the border of its face's patch, where the surface may have a crease or a
// corner (infinitely sharp edges and vertices). There, the sum of the unit
// normals of every face whose surface passes through the point, each weighted
// by its angle there: the angle-weighted pseudonormal of Baerentzen and
// Aanaes, whose side is the side of every point whose nearest surface point
// it is (on a smooth surface all the normals agree, and so does the sum).
Point ClosestPointQuery::Impl::outward(const FaceHit& hit, const Point& normal) const {
  const bool triangle = hit.patch.domain.triangle;
  if (family->has_boundary() || !holes.empty() || !on_patch_border(triangle, hit.x, hit.y)) return normal;
  const Point& p = hit.point;
  // A face through p is within the evaluation's rounding of it; its box, rounded outward, holds p.
  const double magnitude = std::max({std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])});
  const double touch = 4 * tolerance + hit.evaluation + 1e-12 * magnitude;
  FacesNear near{{}, &holes};
  RTCPointQuery query;
  query.x = static_cast<float>(p[0]), query.y = static_cast<float>(p[1]), query.z = static_cast<float>(p[2]);
  query.time = 0;
  query.radius = float_up(touch + 1e-7 * (std::fabs(p[0]) + std::fabs(p[1]) + std::fabs(p[2])));
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(scene, &query, &context, collect_face, &near);
  Point sum{0, 0, 0};
  for (const unsigned g : near.faces) {
    // The face's point nearest p, by the same search restricted to it.
    FaceSearch search(*family, prepared, enclosures, convex, roots, tolerance);
    FaceHit at;
    at.distance = touch;
    const auto centre = SubDomain::unit(triangle).centre();
    search.start(g, centre[0], centre[1], p, at);
    search.add(g, p, at);
    search.run(p, at);
    search.refine(p, at);
    if (!(at.distance < touch) || at.patch.points.empty()) continue;  // the face does not pass through p
    double x = at.x, y = at.y;
    Derivatives d;
    search.derivatives(at.patch, x, y, d);
    const Point n = unit_cross(d.du, d.dv);
    if (!(length(n) > 0)) continue;
    const double w = orientation[g] * domain_angle(triangle, at.x, at.y, d);
    for (int k = 0; k < 3; ++k) sum[k] += w * n[k];
  }
  const double len = length(sum);
  if (!(len > 0)) return normal;
  return {sum[0] / len, sum[1] / len, sum[2] / len};
}

void ClosestPointQuery::Impl::build(const Surface& surface) {
  const auto start = std::chrono::steady_clock::now();
  if (!surface.has_positions()) throw EvaluationError("closest points: the surface has no control positions yet");
  if (!family->hull_bounds())
    throw EvaluationError("closest points: patches of this surface (the tables of '" + topology->tables().scheme() +
                          "') have negative subdivision weights, so control points do not bound the surface");
  prepared = surface.prepared_positions();
  const std::size_t faces = topology->prepared_face_count();
  if (faces > 0xffffffffu) throw EvaluationError("closest points: more than 2^32 prepared faces");

  // Control boxes (Embree's primitives) and the extent that fixes the default tolerance.
  boxes.assign(faces, {});
  const double diagonal = box_diagonal(prepared.data(), prepared.size());
  // The extent checks are on the prepared points, which the queries use.
  if (diagonal == 0) throw EvaluationError("closest points: the control points all coincide (the surface is one point)");
  if (!(diagonal >= limits::kMinQueryExtent)) {
    char extent[32];
    std::snprintf(extent, sizeof extent, "%.3g", diagonal);
    throw EvaluationError(std::string("closest points: the prepared control points span ") + extent +
                          " (bounding-box diagonal), below 1e-100: distances at that scale lose their digits in "
                          "doubles; scale the mesh up");
  }
  // Below 1e-14 of the extent, doubles cannot tell the distances apart and
  // the search would subdivide without end (a fit whose points are a
  // millionth of the control mesh's size asked for that): raised to it.
  // The default is 1e-9 of the control points' diagonal, as documented, and
  // not of the prepared points': a boundary's phantom points reach beyond the
  // control points (a CGAL mesh with six boundary edges: 189 against 113, so
  // 1.7 times the tolerance promised). Where the prepared points span less (a
  // vertex in no face, far off), theirs: never looser than promised. The
  // floor stays on the prepared points' extent: it is what doubles resolve there.
  const double reference = surface.control_diagonal() > 0 ? std::min(diagonal, surface.control_diagonal()) : diagonal;
  tolerance = std::max(options.tolerance > 0 ? options.tolerance : 1e-9 * reference, 1e-14 * diagonal);
  std::vector<SubPatch> patches(faces);
  roots.kinds.assign(faces, 0);
  roots.slabs.assign(faces, {});
  roots.convex.assign(faces, {});
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, faces, 256), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t f = r.begin(); f < r.end(); ++f) {
      family->root(f, prepared.data(), patches[f]);
      Point a = patches[f].points[0], b = a;
      for (const Point& p : patches[f].points)
        for (int k = 0; k < 3; ++k) a[k] = std::min(a[k], p[k]), b[k] = std::max(b[k], p[k]);
      const std::size_t kind = static_cast<std::size_t>(patches[f].kind);
      roots.kinds[f] = patches[f].kind;
      if (kind < enclosures.size() && !enclosures[kind].empty()) {
        roots.slabs[f] = enclosures[kind].slab(patches[f].points);
        // The slab's box where it is inside the control points' (both hold the surface).
        const std::array<Point, 2> slab_box = enclosures[kind].box(roots.slabs[f]);
        for (int k = 0; k < 3; ++k) a[k] = std::max(a[k], slab_box[0][k]), b[k] = std::min(b[k], slab_box[1][k]);
      }
      boxes[f] = {float_down(a[0]), float_down(a[1]), float_down(a[2]), float_up(b[0]), float_up(b[1]), float_up(b[2])};
      if (kind < convex.size() && !convex[kind].empty()) convex[kind].prepare(patches[f].points, roots.convex[f]);
    }
  });

  // Seeds (none on holes), and each prepared face's orientation against its original face.
  holes = topology->prepared_holes();
  std::vector<std::size_t> live;
  for (std::size_t f = 0; f < faces; ++f)
    if (holes.empty() || !holes[f]) live.push_back(f);
  const std::vector<std::array<double, 2>> seed_at = seed_parameters(patches.empty() ? SubDomain() : patches[0].domain);
  const std::size_t per_face = seed_at.size();
  // Seeds only pick where Gauss-Newton starts (the branch and bound then
  // proves the answer with its own evaluations): where evaluation is
  // approximate (non-polynomial schemes between their grids) a loose bound will do.
  seed_tolerance = std::max(tolerance, 1e-4 * diagonal);
  seeds.points.assign(live.size() * per_face, {});
  seeds.faces.assign(live.size() * per_face, 0);
  seeds.at.assign(live.size() * per_face, {});
  orientation.assign(faces, 1);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, live.size(), 64), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t l = r.begin(); l < r.end(); ++l) {
      const std::size_t f = live[l];
      for (std::size_t s = 0; s < per_face; ++s) {
        const std::size_t i = per_face * l + s;
        double x = seed_at[s][0], y = seed_at[s][1];
        seeds.points[i] = family->nearby_point(patches[f], x, y, seed_tolerance).point;
        seeds.faces[i] = f;
        seeds.at[i] = {x, y};
      }
      const FaceParameterReal a = family->original(f, 0.25, 0.25), b = family->original(f, 0.5, 0.25),
                              c = family->original(f, 0.25, 0.5);
      const double det = (b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u);
      orientation[f] = det < 0 ? -1 : 1;
    }
  });
  seed_tree = std::make_unique<SeedTree>(3, seeds, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  seed_tree->buildIndex();

  if (!device.device) throw EvaluationError("closest points: Embree could not create a device");
  if (scene) rtcReleaseScene(scene);
  scene = rtcNewScene(device.device);
  RTCGeometry geometry = rtcNewGeometry(device.device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned>(faces));
  rtcSetGeometryUserData(geometry, &boxes);
  rtcSetGeometryBoundsFunction(geometry, face_bounds, &boxes);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene);
  if (rtcGetDeviceError(device.device) != RTC_ERROR_NONE) throw EvaluationError("closest points: Embree failed to build its BVH");
  build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

ClosestPoint ClosestPointQuery::Impl::find(const Point& q) const {
  for (double c : q) {
    if (!std::isfinite(c)) throw EvaluationError("closest points: a query point has a coordinate that is not finite");
    // Farther out, squared distances overflow and the point would come back as not found.
    if (std::fabs(c) > limits::kMaxCoordinate)
      throw EvaluationError("closest points: a query point has the coordinate " + number_text(c) + ", beyond +-" +
                            number_text(limits::kMaxCoordinate) + " (the limit for control points too)");
  }
  FaceSearch search(*family, prepared, enclosures, convex, roots, tolerance);
  FaceHit best;
  best.distance = options.max_distance;

  // A first upper bound: Gauss-Newton on the patch of the nearest seed (an
  // exact limit point), which is usually the answer already, so that the
  // branch-and-bound below has little left to prove.
  std::size_t nearest = 0;
  double nearest_d2 = 0;
  seed_tree->knnSearch(q.data(), 1, &nearest, &nearest_d2);
  const double seed_distance = std::sqrt(nearest_d2);
  if (seed_distance < best.distance + tolerance + seed_tolerance) {
    const auto& at = seeds.at[nearest];
    FaceHit seeded;
    seeded.distance = INFINITY;
    search.start(seeds.faces[nearest], at[0], at[1], q, seeded);
    if (seeded.distance < best.distance) best = std::move(seeded);
  }

  // Every face whose control box lies within the best distance is queued
  // (Embree visits the boxes the sphere touches), then searched best first.
  QueryState state{&search, q, &best, &holes};
  RTCPointQuery query;
  query.x = static_cast<float>(q[0]), query.y = static_cast<float>(q[1]), query.z = static_cast<float>(q[2]);
  query.time = 0;
  // The float query centre may sit up to half an ulp away from q: widen the radius by that much.
  const double centre_slack = 1e-7 * (std::fabs(q[0]) + std::fabs(q[1]) + std::fabs(q[2]));
  query.radius = std::isfinite(best.distance) ? float_up(best.distance + centre_slack) : INFINITY;
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(scene, &query, &context, visit_face, &state);
  search.run(q, best);
  search.refine(q, best);

  ClosestPoint out;
  if (!(best.distance < options.max_distance)) return out;  // nothing nearer than max_distance
  out.found = true;
  const FaceHit& h = best;
  const FaceParameterReal original = family->original(h.face, h.x, h.y);
  out.face = original.face, out.u = original.u, out.v = original.v;
  out.point = h.point;
  out.distance = h.distance;
  out.accuracy = tolerance + h.gap + h.evaluation;
  // The normal: du x dv of the patch, in the original face's orientation,
  // from the sub-patch the point was found in (exact derivatives there).
  double x = h.x, y = h.y;
  Derivatives d;
  search.derivatives(h.patch, x, y, d);
  Point n = unit_cross(d.du, d.dv);
  if (!(length(n) > 0)) {  // a degenerate parametrisation at this point: the normal a little inside the sub-patch
    const SubPatch& s = h.patch;
    const auto c = s.domain.centre();
    x = h.x + 1e-3 * (c[0] - h.x), y = h.y + 1e-3 * (c[1] - h.y);
    search.derivatives(s, x, y, d);
    n = unit_cross(d.du, d.dv);
  }
  if (length(n) > 0)
    for (int k = 0; k < 3; ++k) out.normal[k] = orientation[h.face] * n[k];
  const double side = dot(minus(q, out.point), outward(h, out.normal));
  out.signed_distance = side < 0 ? -out.distance : out.distance;
  return out;
}

ClosestPointQuery::ClosestPointQuery(const Surface& surface, const ClosestPointOptions& options) : impl_(new Impl) {
  if (!(options.tolerance >= 0) || !std::isfinite(options.tolerance))
    throw EvaluationError("closest points: the tolerance must be a finite number >= 0 (got " + number_text(options.tolerance) + ")");
  if (!(options.max_distance >= 0))
    throw EvaluationError("closest points: the maximum distance must be >= 0 (got " + number_text(options.max_distance) + ")");
  if (options.threads < 0 || options.threads > 256)
    throw EvaluationError("closest points: threads must be 0..256 (got " + std::to_string(options.threads) + ")");
  impl_->topology = surface.shared_topology();
  impl_->family = &impl_->topology->family();
  impl_->options = options;
  for (int kind = 0; kind <= impl_->family->max_kind(); ++kind) {
    const AffineParameters* affine = impl_->family->affine_parameters(kind);
    impl_->enclosures.push_back(affine ? AffineEnclosure(*affine) : AffineEnclosure());
    const PolynomialPatch* polynomial = impl_->family->polynomial_patch(kind);
    impl_->convex.push_back(polynomial ? ConvexBound(*polynomial) : ConvexBound());
  }
  impl_->build(surface);
}

ClosestPointQuery::~ClosestPointQuery() = default;

void ClosestPointQuery::update(const Surface& surface) {
  if (surface.shared_topology() != impl_->topology)
    throw EvaluationError("closest points: update() needs a surface of the topology the query was built for");
  impl_->build(surface);
}

ClosestPoint ClosestPointQuery::find(const Point& q) const { return impl_->find(q); }

std::vector<ClosestPoint> ClosestPointQuery::find(const std::vector<Point>& queries) const {
  std::vector<ClosestPoint> out(queries.size());
  const auto& progress = impl_->options.progress;
  std::atomic<std::size_t> done{0};
  std::mutex reporting;  // one report at a time; a thread that finds it taken goes on
  auto last_report = std::chrono::steady_clock::now();
  tbb::task_arena arena(impl_->options.threads > 0 ? impl_->options.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, queries.size(), 16), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t i = r.begin(); i < r.end(); ++i) {
        try {
          out[i] = impl_->find(queries[i]);
        } catch (const EvaluationError& e) {  // which of the batch, so that a caller can name it
          char at[96];
          std::snprintf(at, sizeof at, "query %zu (%.9g, %.9g, %.9g): ", i, queries[i][0], queries[i][1], queries[i][2]);
          throw EvaluationError(at + std::string(e.what()));
        }
      }
      done += r.size();
      if (progress && reporting.try_lock()) {
        const std::lock_guard<std::mutex> held(reporting, std::adopt_lock);
        const auto now = std::chrono::steady_clock::now();
        if (now - last_report >= std::chrono::seconds(1)) {
          last_report = now;
          progress(done.load(), queries.size());  // read under the lock: reports never go backwards
        }
      }
    });
  });
  return out;
}

double ClosestPointQuery::tolerance() const { return impl_->tolerance; }

std::size_t ClosestPointQuery::memory_bytes() const {
  const Impl& i = *impl_;
  std::size_t bytes = i.prepared.capacity() * sizeof(Point) + i.boxes.capacity() * sizeof(i.boxes[0]) +
                      i.orientation.capacity() + i.seeds.points.capacity() * sizeof(Point) +
                      i.seeds.faces.capacity() * sizeof(std::size_t) + i.seeds.at.capacity() * sizeof(i.seeds.at[0]);
  bytes += i.roots.kinds.capacity() * sizeof(int) + i.roots.slabs.capacity() * sizeof(AffineEnclosure::Slab);
  for (const ConvexBound::Prepared& p : i.roots.convex)
    bytes += sizeof(p) + (p.grid.capacity() + p.net.capacity()) * sizeof(Point) + (p.low.capacity() + p.high.capacity()) * sizeof(double);
  if (i.seed_tree) bytes += i.seed_tree->usedMemory(*i.seed_tree);
  // Embree's BVH over the boxes: about two nodes of 64 bytes per primitive (no API to ask).
  bytes += i.boxes.size() * 128;
  return bytes;
}

double ClosestPointQuery::build_seconds() const { return impl_->build_seconds; }

}  // namespace stencil_runtime
