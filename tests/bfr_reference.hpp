#pragma once
// OpenSubdiv (Bfr) as the reference limit surface for Catmull-Clark and Loop meshes.
// Approximation level 10: every parameter farther than 2^-10 from an
// extraordinary vertex lies in an exact B-spline sub-patch (see
// test_quad_opensubdiv.cpp for the measurements behind this choice).
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <array>
#include <map>
#include <memory>
#include <stdexcept>
#include <vector>

namespace bfr_reference {

namespace osd = OpenSubdiv;

// Semi-sharp creases and corners as Far::TopologyDescriptor takes them.
struct Creasing {
  std::vector<int> crease_pairs;  // two vertices per creased edge
  std::vector<float> crease_sharpness;
  std::vector<int> corners;
  std::vector<float> corner_sharpness;
  bool chaikin = false;
  bool smooth_triangles = false;  // Catmark's TRI_SUB_SMOOTH
  bool boundary_corners = false;  // VTX_BOUNDARY_EDGE_AND_CORNER (default: edge only)
  bool boundary_none = false;     // VTX_BOUNDARY_NONE (faces at boundary vertices have no surface)
};

inline std::unique_ptr<osd::Far::TopologyRefiner> make_refiner(int num_vertices, const std::vector<int>& sizes,
                                                               const std::vector<int>& indices,
                                                               osd::Sdc::SchemeType scheme = osd::Sdc::SCHEME_CATMARK,
                                                               const std::vector<int>& holes = {},
                                                               const Creasing& creasing = {}) {
  osd::Far::TopologyDescriptor desc;
  desc.numVertices = num_vertices;
  desc.numFaces = static_cast<int>(sizes.size());
  desc.numVertsPerFace = sizes.data();
  desc.vertIndicesPerFace = indices.data();
  desc.numHoles = static_cast<int>(holes.size());
  desc.holeIndices = holes.empty() ? nullptr : holes.data();
  desc.numCreases = static_cast<int>(creasing.crease_sharpness.size());
  desc.creaseVertexIndexPairs = creasing.crease_pairs.empty() ? nullptr : creasing.crease_pairs.data();
  desc.creaseWeights = creasing.crease_sharpness.empty() ? nullptr : creasing.crease_sharpness.data();
  desc.numCorners = static_cast<int>(creasing.corner_sharpness.size());
  desc.cornerVertexIndices = creasing.corners.empty() ? nullptr : creasing.corners.data();
  desc.cornerWeights = creasing.corner_sharpness.empty() ? nullptr : creasing.corner_sharpness.data();
  osd::Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(creasing.boundary_none      ? osd::Sdc::Options::VTX_BOUNDARY_NONE
                                   : creasing.boundary_corners ? osd::Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER
                                                               : osd::Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  if (creasing.chaikin) sdc.SetCreasingMethod(osd::Sdc::Options::CREASE_CHAIKIN);
  if (creasing.smooth_triangles) sdc.SetTriangleSubdivision(osd::Sdc::Options::TRI_SUB_SMOOTH);
  using Factory = osd::Far::TopologyRefinerFactory<osd::Far::TopologyDescriptor>;
  return std::unique_ptr<osd::Far::TopologyRefiner>(Factory::Create(desc, Factory::Options(scheme, sdc)));
}

inline constexpr int kApproxLevel = 10;

// Far's vertices after `level` levels of uniform refinement (in double), and,
// with `limit`, their limit points (Far's limit masks; every sharpness must
// have decayed by then).
inline std::vector<std::array<double, 3>> far_points(const std::vector<std::array<double, 3>>& positions,
                                                     const std::vector<int>& sizes, const std::vector<int>& indices,
                                                     osd::Sdc::SchemeType scheme, const Creasing& creasing, int level,
                                                     bool limit) {
  struct Primvar {
    double p[3];
    void Clear() { p[0] = p[1] = p[2] = 0; }
    void AddWithWeight(const Primvar& s, double w) {
      for (int k = 0; k < 3; ++k) p[k] += w * s.p[k];
    }
  };
  auto refiner = make_refiner(static_cast<int>(positions.size()), sizes, indices, scheme, {}, creasing);
  if (!refiner) throw std::runtime_error("OpenSubdiv refused the mesh");
  osd::Far::TopologyRefiner::UniformOptions options(level);
  options.fullTopologyInLastLevel = true;  // the limit masks need it
  refiner->RefineUniform(options);
  std::vector<Primvar> points(static_cast<std::size_t>(refiner->GetNumVerticesTotal()));
  for (std::size_t v = 0; v < positions.size(); ++v)
    for (std::size_t k = 0; k < 3; ++k) points[v].p[k] = positions[v][k];
  osd::Far::PrimvarRefinerReal<double> primvars(*refiner);
  Primvar* src = points.data();
  for (int l = 1; l <= level; ++l) {
    Primvar* dst = src + refiner->GetLevel(l - 1).GetNumVertices();
    primvars.Interpolate(l, src, dst);
    src = dst;
  }
  std::vector<Primvar> last(src, src + refiner->GetLevel(level).GetNumVertices());
  if (limit) {
    Primvar* destination = last.data();
    primvars.Limit(src, destination);
  }
  std::vector<std::array<double, 3>> out;
  for (const Primvar& q : last) out.push_back({q.p[0], q.p[1], q.p[2]});
  return out;
}

// The limit surface of a mesh under `scheme` (Catmull-Clark or Loop); a face's
// (u, v) is Bfr's: for a quad, u along v0->v1 and v along v0->v3; for a
// triangle, u along v0->v1 and v along v0->v2.
class BfrLimit {
 public:
  BfrLimit(const std::vector<std::array<double, 3>>& positions, const std::vector<int>& sizes,
           const std::vector<int>& indices, osd::Sdc::SchemeType scheme = osd::Sdc::SCHEME_CATMARK,
           const std::vector<int>& holes = {}, const Creasing& creasing = {}, int approx_level = kApproxLevel)
      : sizes_(sizes), indices_(indices),
        refiner_(make_refiner(static_cast<int>(positions.size()), sizes_, indices_, scheme, holes, creasing)) {
    if (!refiner_) throw std::runtime_error("OpenSubdiv refused the mesh");
    osd::Bfr::SurfaceFactory::Options options;
    options.SetApproxLevelSmooth(approx_level).SetApproxLevelSharp(approx_level);
    factory_ = std::make_unique<osd::Bfr::RefinerSurfaceFactory<>>(*refiner_, options);
    for (const auto& p : positions) flat_.insert(flat_.end(), p.begin(), p.end());
  }

  // Whether the face has a limit surface (not a hole).
  bool has_surface(int face) const { return factory_->FaceHasLimitSurface(face); }

  std::array<double, 3> evaluate(int face, double u, double v) {
    osd::Bfr::Surface<double> surface;
    const std::vector<double> patch = prepare(face, surface);
    const double uv[2] = {u, v};
    std::array<double, 3> out{};
    surface.Evaluate(uv, patch.data(), 3, out.data());
    return out;
  }

  // The limit point and its partial derivatives d/du, d/dv (Bfr's Evaluate with derivatives).
  std::array<std::array<double, 3>, 3> derivatives(int face, double u, double v) {
    osd::Bfr::Surface<double> surface;
    const std::vector<double> patch = prepare(face, surface);
    const double uv[2] = {u, v};
    std::array<std::array<double, 3>, 3> out{};
    surface.Evaluate(uv, patch.data(), 3, out[0].data(), out[1].data(), out[2].data());
    return out;
  }

  // The limit point, its first and its second partial derivatives (Bfr's Evaluate with
  // second derivatives): point, du, dv, duu, duv, dvv.
  std::array<std::array<double, 3>, 6> second_derivatives(int face, double u, double v) {
    osd::Bfr::Surface<double> surface;
    const std::vector<double> patch = prepare(face, surface);
    const double uv[2] = {u, v};
    std::array<std::array<double, 3>, 6> out{};
    surface.Evaluate(uv, patch.data(), 3, out[0].data(), out[1].data(), out[2].data(), out[3].data(), out[4].data(),
                     out[5].data());
    return out;
  }

  // The limit point's weights over the mesh's control vertices (Bfr's
  // EvaluateStencil over the surface's control points, gathered by vertex).
  std::map<int, double> stencil(int face, double u, double v) {
    osd::Bfr::Surface<double> surface;
    if (!factory_->InitVertexSurface(face, &surface) || !surface.IsValid())
      throw std::runtime_error("Bfr has no surface for face " + std::to_string(face));
    std::vector<int> indices(static_cast<std::size_t>(surface.GetNumControlPoints()));
    surface.GetControlPointIndices(indices.data());
    std::vector<double> weights(indices.size());
    const double uv[2] = {u, v};
    surface.EvaluateStencil(uv, weights.data());
    std::map<int, double> out;
    for (std::size_t k = 0; k < indices.size(); ++k) out[indices[k]] += weights[k];
    return out;
  }

 private:
  // The face's surface and its patch points from the mesh's positions.
  std::vector<double> prepare(int face, osd::Bfr::Surface<double>& surface) const {
    if (!factory_->InitVertexSurface(face, &surface) || !surface.IsValid())
      throw std::runtime_error("Bfr has no surface for face " + std::to_string(face));
    std::vector<double> patch(static_cast<std::size_t>(surface.GetNumPatchPoints()) * 3);
    surface.PreparePatchPoints(flat_.data(), 3, patch.data(), 3);
    return patch;
  }

  std::vector<int> sizes_, indices_;
  std::unique_ptr<osd::Far::TopologyRefiner> refiner_;
  std::unique_ptr<osd::Bfr::RefinerSurfaceFactory<>> factory_;
  std::vector<double> flat_;
};

}  // namespace bfr_reference
