#pragma once
// The distance from a point to a Catmull-Clark or Loop limit surface by brute
// force on OpenSubdiv's Bfr: an oracle for closest points and for fitting errors.
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "bfr_reference.hpp"
#include "stencil_runtime/mesh.hpp"

namespace bfr_reference {

using stencil_runtime::Mesh;
using stencil_runtime::Point;

inline double point_distance(const Point& a, const Point& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

// Every face of a mesh as a cached Bfr surface with its patch points.
class BfrOracle {
 public:
  // `holes`: faces without a surface (Bfr's own hole tags), skipped by distance_to().
  explicit BfrOracle(const Mesh& mesh, osd::Sdc::SchemeType scheme = osd::Sdc::SCHEME_CATMARK,
                     const std::vector<int>& holes = {})
      : refiner_(bfr_reference::make_refiner(static_cast<int>(mesh.vertex_count()), mesh.face_sizes, mesh.face_vertices,
                                             scheme, holes)),
        triangles_(scheme == osd::Sdc::SCHEME_LOOP) {
    osd::Bfr::SurfaceFactory::Options options;
    options.SetApproxLevelSmooth(bfr_reference::kApproxLevel).SetApproxLevelSharp(bfr_reference::kApproxLevel);
    osd::Bfr::RefinerSurfaceFactory<> factory(*refiner_, options);
    std::vector<double> flat;
    for (const Point& p : mesh.positions) flat.insert(flat.end(), p.begin(), p.end());
    faces_.resize(mesh.face_count());
    for (std::size_t f = 0; f < faces_.size(); ++f) {
      if (!factory.FaceHasLimitSurface(static_cast<int>(f))) continue;  // a hole
      REQUIRE(factory.InitVertexSurface(static_cast<int>(f), &faces_[f].surface));
      faces_[f].patch.resize(static_cast<std::size_t>(faces_[f].surface.GetNumPatchPoints()) * 3);
      faces_[f].surface.PreparePatchPoints(flat.data(), 3, faces_[f].patch.data(), 3);
    }
  }

  void evaluate(std::size_t f, double u, double v, Point& p, Point& du, Point& dv) const {
    const double uv[2] = {u, v};
    faces_[f].surface.Evaluate(uv, faces_[f].patch.data(), 3, p.data(), du.data(), dv.data());
  }

  // The distance from q to the surface: 24 x 24 samples per face (the half
  // with u + v <= 1 on Loop's triangles), the best three of each face polished.
  double distance_to(const Point& q) const {
    double best = INFINITY;
    constexpr int kSamples = 24;
    for (std::size_t f = 0; f < faces_.size(); ++f) {
      if (faces_[f].patch.empty()) continue;  // a hole
      std::vector<std::pair<double, std::pair<double, double>>> samples;
      Point p{}, du{}, dv{};
      for (int j = 0; j <= kSamples; ++j)
        for (int i = 0; i <= (triangles_ ? kSamples - j : kSamples); ++i) {
          evaluate(f, double(i) / kSamples, double(j) / kSamples, p, du, dv);
          samples.push_back({point_distance(p, q), {double(i) / kSamples, double(j) / kSamples}});
        }
      std::partial_sort(samples.begin(), samples.begin() + 3, samples.end());
      for (int s = 0; s < 3; ++s) best = std::min(best, polish(f, samples[s].second.first, samples[s].second.second, q));
    }
    return best;
  }

 private:
  // Projected Gauss-Newton with backtracking: a step is taken only where it
  // brings the point nearer (far from the surface plain Gauss-Newton can
  // climb away from the minimum).
  double polish(std::size_t f, double u, double v, const Point& q) const {
    Point p{}, du{}, dv{};
    evaluate(f, u, v, p, du, dv);
    double d = point_distance(p, q);
    for (int step = 0; step < 400; ++step) {
      const Point r{p[0] - q[0], p[1] - q[1], p[2] - q[2]};
      auto dot = [](const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
      const double a = dot(du, du), b = dot(du, dv), c = dot(dv, dv), gu = dot(r, du), gv = dot(r, dv);
      const double det = a * c - b * b;
      // Directions to try: Gauss-Newton, then steepest descent (scaled to a Gauss-Newton-like length).
      std::vector<std::array<double, 2>> directions;
      if (det > 0) directions.push_back({-(c * gu - b * gv) / det, -(a * gv - b * gu) / det});
      const double g = std::hypot(gu, gv);
      if (g > 0) directions.push_back({-gu / g * 0.1, -gv / g * 0.1});
      bool moved = false;
      for (const auto& s : directions) {
        for (double t = 1; t > 1e-12 && !moved; t /= 2) {
          double nu = std::clamp(u + t * s[0], 0.0, 1.0), nv = std::clamp(v + t * s[1], 0.0, 1.0);
          if (triangles_ && nu + nv > 1) {  // back onto the triangle's long edge
            const double excess = 0.5 * (nu + nv - 1);
            nu = std::clamp(nu - excess, 0.0, 1.0), nv = 1 - nu;
          }
          Point np{}, ndu{}, ndv{};
          evaluate(f, nu, nv, np, ndu, ndv);
          const double nd = point_distance(np, q);
          if (nd < d) {
            moved = true;
            u = nu, v = nv, p = np, du = ndu, dv = ndv, d = nd;
          }
        }
        if (moved) break;
      }
      if (!moved) break;
    }
    return d;
  }

  struct Face {
    osd::Bfr::Surface<double> surface;
    std::vector<double> patch;
  };
  std::unique_ptr<osd::Far::TopologyRefiner> refiner_;
  bool triangles_ = false;
  std::vector<Face> faces_;
};

}  // namespace bfr_reference
