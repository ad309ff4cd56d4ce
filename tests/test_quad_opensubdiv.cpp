// Catmull-Clark patch stencils against OpenSubdiv's Bfr (an independent
// implementation of the same limit surface), in double precision.
//
// For valences 3..8 the sector mesh (sector_mesh.hpp) gets random control
// points; our exact stencils W(i/n, j/n) (n = 1..8) are rounded weight by weight
// to double and applied in long double; Bfr evaluates the limit surface of the
// same face at the same (u,v). They must agree to 1e-12 of the mesh's
// bounding-box size at every grid point.
//
// Bfr options. Bfr represents the limit surface of a face with an
// extraordinary vertex by a patch tree (opensubdiv/bfr/irregularPatchBuilder.cpp,
// patchTreeBuilder): the face is refined adaptively towards the EV up to
// L = SurfaceFactory::Options::ApproxLevelSmooth levels (default 2); every
// sub-face that is regular by then is an exact bicubic B-spline patch, and the
// innermost sub-face [0,2^-L]^2 at the EV is a Gregory-basis end cap, which only
// approximates the limit surface inside but interpolates the exact limit
// positions at its corners (so the EV itself is exact at every L).
// Measured on this test's meshes (valences 3..8, n = 1..8, bounding-box
// diagonal about 3.4), largest |ours - Bfr| over the non-EV grid points:
//   L = 0: 8.4e-2, L = 1: 4.5e-2, L = 2 (the default): 1.9e-2 (at (0, 1/8), v = 8),
//   L = 3..12: 4.4e-16; at the EV: <= 2.8e-16 for every L.
// So L >= 3 is needed: then every grid point with n <= 8 other than the EV has
// max(u,v) >= 1/8 = 2^-3 and lies in an exact B-spline sub-patch or on an end
// cap's corner. We run with L = 10 (the sharp level is set alike; the mesh has
// no sharp features near the patch), which costs nothing measurable; the
// agreement then is rounding error (about 1e-16 relative), far inside 1e-12.
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>
#include <opensubdiv/sdc/options.h>
#include <opensubdiv/sdc/types.h>

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <set>
#include <vector>

#include "bfr_reference.hpp"
#include "quad/ev_patch_solver.hpp"
#include "quad/patch_layout.hpp"
#include "quad/quad_scheme_loader.hpp"
#include "sector_mesh.hpp"

namespace {

using namespace OpenSubdiv;

// Refinement levels Bfr uses to approximate the limit surface around the EV
// (see the file comment: any L >= 3 is exact at these grid points, L <= 2 is not).
constexpr int kApproxLevel = bfr_reference::kApproxLevel;
constexpr int kBlocks = 3;     // K: the patch's support reaches chart distance 2 < K
constexpr double kRelTol = 1e-12;

std::unique_ptr<Far::TopologyRefiner> make_refiner(const sector_mesh::SectorMesh& mesh, std::vector<int>& sizes,
                                                   std::vector<Far::Index>& indices) {
  sizes.assign(mesh.faces().size(), 4);
  indices.clear();
  for (const auto& f : mesh.faces()) indices.insert(indices.end(), f.begin(), f.end());
  return bfr_reference::make_refiner(mesh.num_vertices(), sizes, indices);
}

}  // namespace

TEST_CASE("Catmull-Clark EV patch stencils agree with OpenSubdiv Bfr", "[surface][opensubdiv]") {
  const sg::QuadScheme scheme = sg::load_quad_scheme("catmull-clark");

  for (int v = 3; v <= 8; ++v) {
    INFO("valence " << v);
    const sector_mesh::SectorMesh mesh(v, kBlocks);
    REQUIRE(mesh.check_against_layout().empty());
    const auto points = mesh.random_points(20240601u + static_cast<unsigned>(v));

    double extent = 0;  // bounding-box diagonal
    {
      std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
      for (const auto& p : points)
        for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], p[c]), hi[c] = std::max(hi[c], p[c]);
      for (int c = 0; c < 3; ++c) extent += (hi[c] - lo[c]) * (hi[c] - lo[c]);
      extent = std::sqrt(extent);
    }

    std::vector<int> sizes;
    std::vector<Far::Index> indices;
    const auto refiner = make_refiner(mesh, sizes, indices);
    REQUIRE(refiner);

    Bfr::SurfaceFactory::Options options;
    options.SetApproxLevelSmooth(kApproxLevel).SetApproxLevelSharp(kApproxLevel);
    const Bfr::RefinerSurfaceFactory<> factory(*refiner, options);
    Bfr::Surface<double> surface;
    REQUIRE(factory.InitVertexSurface(mesh.patch_face(), &surface));
    REQUIRE(surface.IsValid());
    CHECK(surface.IsRegular() == (v == 4));

    // Bfr's quad parameterisation: corner k of the face (EV, e_0, f_0, e_1) at
    // (0,0), (1,0), (1,1), (0,1) -- the same as ours (u towards e_0, w towards e_1).
    const Bfr::Parameterization param = surface.GetParameterization();
    REQUIRE(param.GetType() == Bfr::Parameterization::QUAD);
    const double expected_uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int k = 0; k < 4; ++k) {
      double uv[2];
      param.GetVertexCoord(k, uv);
      CHECK(uv[0] == expected_uv[k][0]);
      CHECK(uv[1] == expected_uv[k][1]);
    }

    // Bfr's control points are exactly our 2v+8 patch points.
    std::vector<Far::Index> cvs(static_cast<std::size_t>(surface.GetNumControlPoints()));
    surface.GetControlPointIndices(cvs.data());
    CHECK(std::set<int>(cvs.begin(), cvs.end()) ==
          std::set<int>(mesh.patch_vertices().begin(), mesh.patch_vertices().end()));

    std::vector<double> flat(points.size() * 3);
    for (std::size_t p = 0; p < points.size(); ++p)
      for (int c = 0; c < 3; ++c) flat[3 * p + c] = points[p][c];
    std::vector<double> patch_points(static_cast<std::size_t>(surface.GetNumPatchPoints()) * 3);
    surface.PreparePatchPoints(flat.data(), 3, patch_points.data(), 3);

    double worst = 0;
    for (long n = 1; n <= 8; ++n) {
      INFO("n = " << n);
      const sg::PatchGrid grid = sg::solve_ev_patch(scheme, v, n);
      REQUIRE(grid.grid == n);
      for (long j = 0; j <= n; ++j)
        for (long i = 0; i <= n; ++i) {
          const auto& w = grid.at(i, j);
          REQUIRE(w.size() == static_cast<std::size_t>(2 * v + 8));
          std::array<long double, 3> ours{0, 0, 0};
          for (std::size_t h = 0; h < w.size(); ++h) {
            const long double wh = sg::to_double(w[h]);
            const auto& p = points[static_cast<std::size_t>(mesh.patch_vertices()[h])];
            for (int c = 0; c < 3; ++c) ours[c] += wh * p[c];
          }
          const double uv[2] = {double(i) / double(n), double(j) / double(n)};
          double bfr[3];
          surface.Evaluate(uv, patch_points.data(), 3, bfr);
          double err = 0;
          for (int c = 0; c < 3; ++c) err = std::max(err, std::fabs(double(ours[c] - bfr[c])));
          worst = std::max(worst, err / extent);
          INFO("i = " << i << ", j = " << j << ", |ours - Bfr| / extent = " << err / extent);
          CHECK(err <= kRelTol * extent);
        }
    }
    INFO("largest relative difference " << worst);
    SUCCEED();
  }
}
