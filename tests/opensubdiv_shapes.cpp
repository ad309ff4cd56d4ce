// check_opensubdiv_shapes: the runtime against OpenSubdiv on OpenSubdiv's own
// regression shapes (regression/shapes/catmark_*.h and loop_*.h of its source,
// extracted to OBJ files by scripts/opensubdiv-shapes.sh; they are not
// bundled). For every shape: either the runtime refuses it (the message is
// printed), or every node of every face at rate 4 (each sub-face of an N-gon
// likewise) and three random parameters per face, and the unit normal there,
// are compared with Bfr.
//
// Where Bfr disagrees by more than 1e-10 of the bounding box's diagonal, Bfr
// may be the approximate one: it evaluates irregular features (infinitely
// sharp ones, extraordinary corners with sharp neighbours) on a patch tree
// refined to a finite "approximation level". Such a sample counts as agreeing
// when Bfr's distance to our value shrinks at levels 6, 8, 10 (its
// approximation converges to ours), or, at a face corner of a mesh without
// infinitely sharp tags, when our value equals Far's limit point of that
// vertex after the semi-sharp features have decayed (uniform refinement,
// then Far's limit masks: exact once every vertex is smooth or on a boundary;
// Bfr's vertex limit under Chaikin's creasing method is not). Under Chaikin's
// method Bfr is off near crease vertices inside faces too, so there the random
// parameters are nodes of Far's uniform refinement at level max(6, sharpness)
// and such a sample also agrees when it equals Far's limit point there. A
// sample where none of these holds is a mismatch: the exit status is 1.
//
// With --nonpoly, the Catmull-Clark shapes are also evaluated under nonpoly,
// which OpenSubdiv cannot evaluate: there the oracle is continuity. At nine
// points along every edge between two quads (a mesh edge in exactly two
// faces, the second face's parameters found from its own corners) both faces
// must give the same point, to 1e-12 of the diagonal, and, inside the edge
// and off infinitely sharp edges, the same unit normal to 1e-10.
//
// Closest points on every shape evaluated (its own scheme): 300 query points
// uniform in the box of twice the bounding box's volume (seed 000's protocol)
// and 100 on or near the surface, against brute force: the nearest of the
// exact limit points at every rate-8 node, then Gauss-Newton from the eight
// nearest nodes within their (quad or triangle) faces. No reported distance
// may exceed the brute force's by more than the tolerance (1e-9 of the
// diagonal), and the reported point must be the surface's point at the
// reported parameters (1e-12).
//
//   check_opensubdiv_shapes CC.sgs LOOP.sgt [--nonpoly NONPOLY.sgs] SHAPE.obj ...
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "bfr_reference.hpp"
#include "stencil_runtime/closest_point.hpp"
#include "stencil_runtime/stencil_runtime.hpp"

namespace {

using namespace stencil_runtime;
namespace osd = OpenSubdiv;

using Vec = std::array<double, 3>;

struct Box {
  Vec lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  double diagonal() const { return std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]); }
};

// The control points' bounding box: differences are measured against its diagonal.
Box bounding_box(const Mesh& mesh) {
  Box b;
  for (const Point& p : mesh.positions)
    for (int k = 0; k < 3; ++k) b.lo[k] = std::min(b.lo[k], p[k]), b.hi[k] = std::max(b.hi[k], p[k]);
  return b;
}

double max_abs_diff(const Vec& a, const Vec& b) {
  double d = 0;
  for (int k = 0; k < 3; ++k) d = std::max(d, std::fabs(a[k] - b[k]));
  return d;
}

double norm(const Vec& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

// Bfr's unit normal from its derivatives; false where they are (nearly)
// parallel or vanish, so that the normal has no digits to compare.
bool unit_cross(const Vec& du, const Vec& dv, Vec& n) {
  n = {du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0]};
  const double length = norm(n);
  if (!(length > 1e-9 * norm(du) * norm(dv)) || !(length > 0)) return false;
  for (double& c : n) c /= length;
  return true;
}

struct Sample {
  std::size_t face;
  double u, v;
  int corner_vertex;  // the mesh vertex at this parameter, or -1
};

// The nodes at `rate` of every face with a surface, in Bfr's parameterization
// (an N-gon's: of each sub-face, at that rate), and `random` parameters per
// face drawn uniformly from its domain (a quad's square, a triangle's
// triangle, an N-gon's sub-faces), off every grid: evaluation at any
// parameter, not only at the tables' nodes. With `dyadic` > 0 the random
// parameters are rounded to multiples of 2^-dyadic (an N-gon's sub-face: of
// 2^-(dyadic+1)), nodes of Far's uniform refinement at that level.
std::vector<Sample> samples_of(const Mesh& mesh, const SurfaceTopology& topology, int rate, int random, int dyadic = 0) {
  std::vector<Sample> out;
  std::size_t first = 0;
  for (std::size_t f = 0; f < mesh.face_sizes.size(); first += static_cast<std::size_t>(mesh.face_sizes[f]), ++f) {
    if (topology.is_hole(f)) continue;
    const FaceDomain d = topology.domain(f);
    auto corner = [&](int c) { return mesh.face_vertices[first + static_cast<std::size_t>(c)]; };
    std::mt19937_64 rng(0x5eed + f);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int k = 0; k < random; ++k) {
      double u = unit(rng), v = unit(rng);
      if (d.kind == FaceDomain::Kind::Triangle && u + v > 1) u = 1 - u, v = 1 - v;
      if (dyadic > 0) {
        const double n = std::ldexp(1.0, dyadic);
        u = std::floor(u * n) / n, v = std::floor(v * n) / n;
      }
      if (d.kind != FaceDomain::Kind::Quad && d.kind != FaceDomain::Kind::Triangle) {
        const int s = static_cast<int>(rng() % static_cast<unsigned>(d.corners));
        u = s % d.u_tiles + 0.5 * u, v = s / d.u_tiles + 0.5 * v;
      }
      out.push_back({f, u, v, -1});
    }
    if (d.kind == FaceDomain::Kind::Quad) {
      for (int a = 0; a <= rate; ++a)
        for (int b = 0; b <= rate; ++b) {
          int vertex = -1;
          if ((a == 0 || a == rate) && (b == 0 || b == rate)) vertex = corner(a == 0 ? (b == 0 ? 0 : 3) : (b == 0 ? 1 : 2));
          out.push_back({f, a / double(rate), b / double(rate), vertex});
        }
    } else if (d.kind == FaceDomain::Kind::Triangle) {
      for (int a = 0; a <= rate; ++a)
        for (int b = 0; a + b <= rate; ++b) {
          int vertex = -1;
          if (a == 0 && b == 0) vertex = corner(0);
          if (a == rate) vertex = corner(1);
          if (b == rate) vertex = corner(2);
          out.push_back({f, a / double(rate), b / double(rate), vertex});
        }
    } else {
      for (int s = 0; s < d.corners; ++s)
        for (int a = 0; a <= rate; ++a)
          for (int b = 0; b <= rate; ++b)
            out.push_back({f, s % d.u_tiles + a / (2.0 * rate), s / d.u_tiles + b / (2.0 * rate), a == 0 && b == 0 ? corner(s) : -1});
    }
  }
  return out;
}

bfr_reference::Creasing creasing_of(const Mesh& mesh) {
  bfr_reference::Creasing c;
  for (const auto& e : mesh.tags.creases) {
    c.crease_pairs.push_back(e.a);
    c.crease_pairs.push_back(e.b);
    c.crease_sharpness.push_back(static_cast<float>(e.sharpness));
  }
  for (const auto& e : mesh.tags.corners) {
    c.corners.push_back(e.vertex);
    c.corner_sharpness.push_back(static_cast<float>(e.sharpness));
  }
  c.chaikin = mesh.tags.chaikin_creases;
  c.smooth_triangles = mesh.tags.smooth_triangles;
  c.boundary_corners = mesh.tags.boundary == BoundaryInterpolation::EdgeAndCorner;
  c.boundary_none = mesh.tags.boundary == BoundaryInterpolation::None;
  return c;
}

// Bfr's point and unit normal at a sample (normal_ok false where its derivatives are parallel).
void bfr_evaluate(bfr_reference::BfrLimit& bfr, const Sample& s, Vec& point, Vec& normal, bool& normal_ok) {
  const auto d = bfr.derivatives(static_cast<int>(s.face), s.u, s.v);
  point = d[0];
  normal_ok = unit_cross(d[1], d[2], normal);
}

struct ShapeResult {
  std::size_t samples = 0, bfr_approximate = 0, far_limit = 0, mismatches = 0, no_normal = 0;
  double position = 0, normal = 0;  // largest difference to Bfr (level 10), positions over the diagonal
  std::string worst;
};

ShapeResult check_shape(const Mesh& mesh, const Surface& surface, bool loop) {
  const bfr_reference::Creasing creasing = creasing_of(mesh);
  std::vector<int> holes;
  for (const auto& h : mesh.tags.holes) holes.push_back(h.face);
  const auto scheme = loop ? osd::Sdc::SCHEME_LOOP : osd::Sdc::SCHEME_CATMARK;
  const std::vector<Vec> positions(mesh.positions.begin(), mesh.positions.end());
  auto bfr_at = [&](int level) {
    return bfr_reference::BfrLimit(positions, mesh.face_sizes, mesh.face_vertices, scheme, holes, creasing, level);
  };
  bfr_reference::BfrLimit bfr10 = bfr_at(10), bfr8 = bfr_at(8), bfr6 = bfr_at(6);

  const double diagonal = bounding_box(mesh).diagonal();
  const double tolerance = 1e-10;

  // Far's limit points at the original vertices, once the semi-sharp features
  // have decayed (no infinitely sharp tag: Far's limit masks at darts and
  // irregular sharp corners are approximations).
  bool infinite = false;
  float sharpest = 0;
  for (const auto& e : mesh.tags.creases) infinite |= e.sharpness >= 10, sharpest = std::max(sharpest, float(e.sharpness));
  for (const auto& e : mesh.tags.corners) infinite |= e.sharpness >= 10, sharpest = std::max(sharpest, float(e.sharpness));
  std::vector<Vec> far_limit;
  // Under Chaikin's creasing Bfr's patches near a crease vertex are not the
  // limit surface (on loop_chaikin1, 2e-3 of the size off Far's limit points
  // at rate-64 nodes of a face, where ours equals them to 1e-15), so there
  // the random parameters are nodes of Far's uniform refinement at level
  // `dyadic` and a sample Bfr does not match is compared with Far's limit
  // points at that level (sorted by x for the lookup).
  int dyadic = 0;
  std::vector<Vec> far_nodes;
  if (!infinite && holes.empty()) {
    const int levels = std::max(1, static_cast<int>(std::ceil(sharpest)));
    far_limit = bfr_reference::far_points(positions, mesh.face_sizes, mesh.face_vertices, scheme, creasing, levels, true);
    if (mesh.tags.chaikin_creases) {
      dyadic = std::max(levels, 6);
      far_nodes = bfr_reference::far_points(positions, mesh.face_sizes, mesh.face_vertices, scheme, creasing, dyadic, true);
      std::sort(far_nodes.begin(), far_nodes.end());
    }
  }
  const auto nearest_far_node = [&](const Vec& p) {
    double nearest = INFINITY;
    const double reach = 1e-6 * diagonal;
    for (auto it = std::lower_bound(far_nodes.begin(), far_nodes.end(), Vec{p[0] - reach, -INFINITY, -INFINITY});
         it != far_nodes.end() && (*it)[0] <= p[0] + reach; ++it)
      nearest = std::min(nearest, max_abs_diff(p, *it));
    return nearest;
  };

  ShapeResult r;
  char where[160];
  for (const Sample& s : samples_of(mesh, surface.topology(), 4, 3, dyadic)) {
    ++r.samples;
    // Faces without a surface (holes, and with boundary interpolation `none`
    // the faces at boundary vertices) must be the same.
    Point ours{};
    bool ours_has_surface = true;
    try {
      ours = surface.evaluate(s.face, s.u, s.v, 0.0).point;
    } catch (const EvaluationError&) {
      ours_has_surface = false;
    }
    if (ours_has_surface != bfr10.has_surface(static_cast<int>(s.face))) {
      ++r.mismatches;
      if (r.worst.empty()) r.worst = "face " + std::to_string(s.face) + (ours_has_surface ? ": a surface where Bfr has none" : ": no surface where Bfr has one");
      continue;
    }
    if (!ours_has_surface) continue;
    bool ours_normal_ok = true;
    const Vec ours_normal = [&]() -> Vec {
      try {
        return surface.normal(s.face, s.u, s.v);
      } catch (const EvaluationError&) {
        ours_normal_ok = false;  // no tangent plane there (docs/runtime.md, "Boundaries")
        return {0, 0, 0};
      }
    }();
    Vec p10{}, n10{};
    bool n10_ok = false;
    bfr_evaluate(bfr10, s, p10, n10, n10_ok);
    const double dp = max_abs_diff(ours, p10) / diagonal;
    const bool compare_normals = ours_normal_ok && n10_ok;
    if (n10_ok && !ours_normal_ok) ++r.no_normal;
    const double dn = compare_normals ? max_abs_diff(ours_normal, n10) : 0;
    if (dp > r.position) r.position = dp;
    if (dn > r.normal) r.normal = dn;
    if (dp <= tolerance && dn <= 1e-8) continue;
    // Bfr's approximation converging to ours?
    Vec p8{}, n8{}, p6{}, n6{};
    bool n8_ok = false, n6_ok = false;
    bfr_evaluate(bfr8, s, p8, n8, n8_ok);
    bfr_evaluate(bfr6, s, p6, n6, n6_ok);
    auto converges = [](double d6, double d8, double d10, double floor) {
      return d10 <= floor || (d10 < 0.8 * d8 && d8 < 0.8 * d6);
    };
    const bool position_converges = converges(max_abs_diff(ours, p6) / diagonal, max_abs_diff(ours, p8) / diagonal, dp, tolerance);
    const bool normal_converges =
        !compare_normals || !n8_ok || !n6_ok || converges(max_abs_diff(ours_normal, n6), max_abs_diff(ours_normal, n8), dn, 1e-8);
    if (position_converges && normal_converges) {
      ++r.bfr_approximate;
      continue;
    }
    if (s.corner_vertex >= 0 && !far_limit.empty() &&
        max_abs_diff(ours, far_limit[static_cast<std::size_t>(s.corner_vertex)]) / diagonal <= tolerance) {
      ++r.far_limit;
      continue;
    }
    if (!far_nodes.empty() && nearest_far_node(ours) / diagonal <= tolerance) {
      ++r.far_limit;
      continue;
    }
    ++r.mismatches;
    std::snprintf(where, sizeof where, "face %zu (%g, %g): position %.2e, normal %.2e", s.face, s.u, s.v, dp, dn);
    if (r.worst.empty()) r.worst = where;
  }
  return r;
}

struct SeamResult {
  std::size_t edges = 0, mismatches = 0;
  double position = 0, normal = 0;  // largest gaps: positions over the diagonal
  std::string worst;
};

// Continuity of a quad scheme's surface across the edges between two quads.
SeamResult check_seams(const Mesh& mesh, const Surface& surface) {
  const SurfaceTopology* topology = &surface.topology();
  const double diagonal = bounding_box(mesh).diagonal();
  // Each directed edge a -> b of a quad with a surface: its face and which edge of the face it is.
  struct Side {
    std::size_t face;
    int edge;
  };
  std::map<std::pair<int, int>, std::vector<Side>> sides;
  std::map<std::pair<int, int>, int> faces_at_edge;
  std::size_t first = 0;
  for (std::size_t f = 0; f < mesh.face_sizes.size(); first += static_cast<std::size_t>(mesh.face_sizes[f]), ++f) {
    const int n = mesh.face_sizes[f];
    for (int k = 0; k < n; ++k) {
      const int a = mesh.face_vertices[first + static_cast<std::size_t>(k)];
      const int b = mesh.face_vertices[first + static_cast<std::size_t>((k + 1) % n)];
      ++faces_at_edge[{std::min(a, b), std::max(a, b)}];
      if (n == 4 && !topology->is_hole(f)) sides[{a, b}].push_back({f, k});
    }
  }
  std::map<std::pair<int, int>, double> sharpness;
  for (const auto& e : mesh.tags.creases) sharpness[{std::min(e.a, e.b), std::max(e.a, e.b)}] = e.sharpness;
  // The point at t along edge k of a quad (corner k to corner k + 1).
  auto along = [](int k, double t, double& u, double& v) {
    static const double cu[5] = {0, 1, 1, 0, 0}, cv[5] = {0, 0, 1, 1, 0};
    u = cu[k] + t * (cu[k + 1] - cu[k]);
    v = cv[k] + t * (cv[k + 1] - cv[k]);
  };
  SeamResult r;
  char where[160];
  for (const auto& [ab, here] : sides) {
    const auto [a, b] = ab;
    if (a > b || here.size() != 1) continue;
    const auto there = sides.find({b, a});
    if (there == sides.end() || there->second.size() != 1 || faces_at_edge[{a, b}] != 2) continue;
    ++r.edges;
    const auto tag = sharpness.find({a, b});
    const bool smooth_across = tag == sharpness.end() || tag->second < 10;
    for (int q = 0; q <= 8; ++q) {
      double u1, v1, u2, v2;
      along(here[0].edge, q / 8.0, u1, v1);
      along(there->second[0].edge, 1 - q / 8.0, u2, v2);
      const Point p1 = surface.evaluate(here[0].face, u1, v1, 0.0).point;
      const Point p2 = surface.evaluate(there->second[0].face, u2, v2, 0.0).point;
      const double dp = max_abs_diff(p1, p2) / diagonal;
      double dn = 0;
      if (smooth_across && q > 0 && q < 8)
        dn = max_abs_diff(surface.normal(here[0].face, u1, v1), surface.normal(there->second[0].face, u2, v2));
      r.position = std::max(r.position, dp);
      r.normal = std::max(r.normal, dn);
      if (dp > 1e-12 || dn > 1e-10) {
        ++r.mismatches;
        std::snprintf(where, sizeof where, "edge %d-%d at %g: position %.2e, normal %.2e", a, b, q / 8.0, dp, dn);
        if (r.worst.empty()) r.worst = where;
      }
    }
  }
  return r;
}

struct DistanceResult {
  std::size_t queries = 0, violations = 0;
  double above_dense = -1e300, off_surface = 0;  // over the diagonal
  std::string worst;
};

// Closest points against brute force over the rate-8 nodes.
DistanceResult check_distances(const Mesh& mesh, const Surface& surface) {
  const Box box = bounding_box(mesh);
  const double diagonal = box.diagonal();
  struct Node {
    Point point;
    Sample at;
    FaceDomain::Kind kind;
  };
  std::vector<Node> dense;
  for (const Sample& s : samples_of(mesh, surface.topology(), 8, 0)) {
    try {
      dense.push_back({surface.evaluate(s.face, s.u, s.v, 0.0).point, s, surface.topology().domain(s.face).kind});
    } catch (const EvaluationError&) {  // no surface there (boundary interpolation `none`)
    }
  }
  DistanceResult r;
  if (dense.empty()) return r;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-0.5, 0.5);
  std::normal_distribution<double> offset(0, 1e-3 * diagonal);
  std::vector<Point> queries;
  const double grow = std::cbrt(2.0);  // twice the volume
  for (int k = 0; k < 300; ++k) {
    Point p;
    for (int j = 0; j < 3; ++j) p[j] = (box.lo[j] + box.hi[j]) / 2 + unit(rng) * (box.hi[j] - box.lo[j]) * grow;
    queries.push_back(p);
  }
  for (int k = 0; k < 100; ++k) {
    Point p = dense[rng() % dense.size()].point;
    if (k % 4 != 0)  // a quarter on the surface itself
      for (double& c : p) c += offset(rng);
    queries.push_back(p);
  }
  ClosestPointOptions options;
  options.threads = 1;
  const ClosestPointQuery query(surface, options);
  const std::vector<ClosestPoint> found = query.find(queries);
  char where[256];
  for (std::size_t k = 0; k < queries.size(); ++k) {
    ++r.queries;
    const Point& q = queries[k];
    auto distance = [&](const Point& p) { return std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]); };
    // The eight nearest nodes, then Gauss-Newton from each (the node itself on an N-gon's sub-faces).
    std::vector<std::pair<double, std::size_t>> order;
    for (std::size_t i = 0; i < dense.size(); ++i) order.push_back({distance(dense[i].point), i});
    const std::size_t seeds = std::min<std::size_t>(8, order.size());
    std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(seeds), order.end());
    double nearest = order[0].first;
    for (std::size_t i = 0; i < seeds; ++i) {
      const Node& n = dense[order[i].second];
      if (n.kind == FaceDomain::Kind::QuadSubfaces) continue;
      const bool triangle = n.kind == FaceDomain::Kind::Triangle;
      auto inside = [&](double& u, double& v) {  // the nearest parameter in the face's domain
        u = std::clamp(u, 0.0, 1.0), v = std::clamp(v, 0.0, 1.0);
        if (triangle && u + v > 1) {
          const double excess = (u + v - 1) / 2;
          u = std::clamp(u - excess, 0.0, 1.0), v = 1 - u;
        }
      };
      double u = n.at.u, v = n.at.v, here = order[i].first;
      for (int iteration = 0; iteration < 20; ++iteration) {
        Derivatives d;
        try {
          d = surface.derivatives(n.at.face, u, v);
        } catch (const EvaluationError&) {  // at an extraordinary vertex: nudge inside
          u += 1e-7 * (1 / 3.0 - u), v += 1e-7 * (1 / 3.0 - v);
          continue;
        }
        const Vec r{d.point[0] - q[0], d.point[1] - q[1], d.point[2] - q[2]};
        auto dot = [](const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
        const double a = dot(d.du, d.du), b = dot(d.du, d.dv), c = dot(d.dv, d.dv), gu = dot(d.du, r), gv = dot(d.dv, r);
        const double det = a * c - b * b;
        if (!(det > 0)) break;
        double step = 1;
        bool better = false;
        for (int halving = 0; halving < 30 && !better; ++halving, step /= 2) {
          double nu = u - step * (c * gu - b * gv) / det, nv = v - step * (a * gv - b * gu) / det;
          inside(nu, nv);
          try {
            const double there = distance(surface.evaluate(n.at.face, nu, nv, 0.0).point);
            if (there < here) here = there, u = nu, v = nv, better = true;
          } catch (const EvaluationError&) {
          }
        }
        if (!better) break;
      }
      nearest = std::min(nearest, here);
    }
    if (!found[k].found) {
      ++r.violations;
      if (r.worst.empty()) r.worst = "query " + std::to_string(k) + ": no point found";
      continue;
    }
    const double above = (found[k].distance - nearest) / diagonal;
    const double off = max_abs_diff(surface.evaluate(found[k].face, found[k].u, found[k].v, 0.0).point, found[k].point) / diagonal;
    r.above_dense = std::max(r.above_dense, above);
    r.off_surface = std::max(r.off_surface, off);
    if (above > 1e-9 || off > 1e-12) {
      ++r.violations;
      std::snprintf(where, sizeof where, "query %zu (%.17g %.17g %.17g): %.2e above brute force, %.2e off the surface", k, q[0],
                    q[1], q[2], above, off);
      if (r.worst.empty()) r.worst = where;
    }
  }
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::vector<std::string> args(argv + 1, argv + argc);
    std::shared_ptr<const Tables> nonpoly_tables;
    if (args.size() >= 4 && args[2] == "--nonpoly") {
      nonpoly_tables = Tables::load(args[3]);
      args.erase(args.begin() + 2, args.begin() + 4);
    }
    if (args.size() < 3) {
      std::fprintf(stderr, "usage: check_opensubdiv_shapes CATMULL_CLARK.sgs LOOP.sgt [--nonpoly NONPOLY.sgs] SHAPE.obj ...\n");
      return 2;
    }
    const auto quad_tables = Tables::load(args[0]);
    const auto loop_tables = Tables::load(args[1]);
    const std::vector<std::string> shapes(args.begin() + 2, args.end());
    // One pass over the shapes (each read and prepared once per scheme: the
    // preparation of a shape with high sharpness is the slow part); the three
    // tables are printed at the end, a progress line per shape on stderr.
    std::string bfr_rows, seam_rows, distance_rows;
    int evaluated = 0, refused = 0, failed = 0;
    int seam_evaluated = 0, seam_refused = 0, seam_failed = 0;
    int distance_evaluated = 0, distance_failed = 0;
    char row[1024];
    std::size_t done = 0;
    for (const std::string& path : shapes) {
      const std::string name = path.substr(path.find_last_of('/') + 1);
      std::fprintf(stderr, "check_opensubdiv_shapes: %zu/%zu %s\n", ++done, shapes.size(), name.c_str());
      const bool loop = name.rfind("loop", 0) == 0;
      if (!loop && name.rfind("catmark", 0) != 0) continue;  // bilinear shapes: no such scheme here
      Mesh mesh;
      try {
        mesh = read_obj(path);
      } catch (const Error& e) {  // refused in both tables, as the surface would be
        ++refused;
        std::snprintf(row, sizeof row, "| %s | | | refused: %s | | | | | |\n", name.c_str(), e.what());
        bfr_rows += row;
        if (nonpoly_tables && !loop) {
          ++seam_refused;
          std::snprintf(row, sizeof row, "| %s | | refused: %s | | |\n", name.c_str(), e.what());
          seam_rows += row;
        }
        continue;
      }
      try {
        const Surface surface(SurfaceTopology::create(loop ? loop_tables : quad_tables, mesh), mesh.positions);
        const ShapeResult r = check_shape(mesh, surface, loop);
        ++evaluated;
        if (r.mismatches) ++failed;
        std::snprintf(row, sizeof row, "| %s | %zu | %zu | %.1e | %.1e | %zu | %zu | %zu | %zu%s%s |\n", name.c_str(),
                      mesh.face_sizes.size(), r.samples, r.position, r.normal, r.bfr_approximate, r.far_limit, r.no_normal,
                      r.mismatches, r.worst.empty() ? "" : ": ", r.worst.c_str());
        bfr_rows += row;
        // Past here the shape is evaluated: an error from a closest point (or
        // from evaluating at what it returned) is a failure, not a refusal.
        ++distance_evaluated;
        try {
          const DistanceResult d = check_distances(mesh, surface);
          if (d.violations) ++distance_failed;
          std::snprintf(row, sizeof row, "| %s | %zu | %.1e | %.1e | %zu%s%s |\n", name.c_str(), d.queries, d.above_dense,
                        d.off_surface, d.violations, d.worst.empty() ? "" : ": ", d.worst.c_str());
        } catch (const Error& e) {
          ++distance_failed;
          std::snprintf(row, sizeof row, "| %s | | | | failed: %s |\n", name.c_str(), e.what());
        }
        distance_rows += row;
      } catch (const Error& e) {
        ++refused;
        std::snprintf(row, sizeof row, "| %s | | | refused: %s | | | | | |\n", name.c_str(), e.what());
        bfr_rows += row;
      }
      if (!nonpoly_tables || loop) continue;
      try {
        const SeamResult r = check_seams(mesh, Surface(SurfaceTopology::create(nonpoly_tables, mesh), mesh.positions));
        ++seam_evaluated;
        if (r.mismatches) ++seam_failed;
        std::snprintf(row, sizeof row, "| %s | %zu | %.1e | %.1e | %zu%s%s |\n", name.c_str(), r.edges, r.position, r.normal,
                      r.mismatches, r.worst.empty() ? "" : ": ", r.worst.c_str());
      } catch (const Error& e) {
        ++seam_refused;
        std::snprintf(row, sizeof row, "| %s | | refused: %s | | |\n", name.c_str(), e.what());
      }
      seam_rows += row;
    }
    std::printf("| shape | faces | samples | largest position difference to Bfr / diagonal | largest normal difference | Bfr approximate (converging to ours) | Far's limit instead | no normal here (Bfr has one) | mismatches |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|\n%s", bfr_rows.c_str());
    std::printf("\n%d shapes evaluated (%d with mismatches), %d refused\n", evaluated, failed, refused);
    if (nonpoly_tables) {
      std::printf("\nnonpoly on the Catmull-Clark shapes, across the edges between two quads:\n\n");
      std::printf("| shape | edges | largest position gap / diagonal | largest normal gap | mismatches |\n|---|---|---|---|---|\n%s",
                  seam_rows.c_str());
      std::printf("\nnonpoly: %d shapes evaluated (%d with gaps), %d refused\n", seam_evaluated, seam_failed, seam_refused);
    }
    std::printf("\nClosest points (each shape under its own scheme) against brute force (rate-8 nodes, then Gauss-Newton):\n\n");
    std::printf("| shape | queries | largest excess over brute force / diagonal | largest distance of the point from the surface | violations |\n|---|---|---|---|---|\n%s",
                distance_rows.c_str());
    std::printf("\nclosest points: %d shapes (%d with violations)\n", distance_evaluated, distance_failed);
    return failed || seam_failed || distance_failed ? 1 : 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "check_opensubdiv_shapes: %s\n", e.what());
    return 1;
  }
}
