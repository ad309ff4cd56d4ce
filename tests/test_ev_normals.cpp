// Normals at extraordinary vertices, where the surface has no parametric
// derivative: Surface::normal uses the tables' tangent stencils (left
// eigenvectors of the patch's subdivision matrix A0 for its subdominant
// eigenvalue, generator/quad/ev_tangents.hpp). Checked against
//  - OpenSubdiv's exact limit tangents at the vertex (Far::PrimvarRefiner::Limit,
//    Sdc's limit tangent masks: Catmull-Clark);
//  - the normals from the derivatives at parameters approaching the vertex
//    (every quad scheme: they converge to the tangent plane);
//  - the eigen-relation itself, in doubles with Eigen on the tables' A0
//    (separate code from the generator's high-precision inverse iteration);
//  - the agreement of the normals that the faces around a vertex give.
#include <catch2/catch.hpp>
#include <Eigen/Dense>
#include <opensubdiv/far/primvarRefiner.h>

#include <cmath>
#include <filesystem>

#include "bfr_reference.hpp"
#include "cli.hpp"
#include "runtime_api.hpp"
#include "runtime_checks.hpp"
#include "tables/quad_tables.hpp"

using namespace stencil_runtime;
using namespace test_runtime;
namespace fs = std::filesystem;

namespace {

const fs::path kMeshes = fs::path(STENCIL_SOURCE_DIR) / "meshes";
const char* kBundled[] = {"cube", "torus-3-5", "chess-piece", "bumpy-sphere"};

fs::path tables_for(const std::string& scheme) { return generated_table(scheme, "--valence 3-8 --n 24", "sgs"); }

struct Primvar {
  double p[3] = {0, 0, 0};
  void Clear(void* = nullptr) { p[0] = p[1] = p[2] = 0; }
  void AddWithWeight(const Primvar& s, float w) { AddWithWeight(s, static_cast<double>(w)); }
  void AddWithWeight(const Primvar& s, double w) {
    for (int k = 0; k < 3; ++k) p[k] += w * s.p[k];
  }
};

Point cross(const Point& a, const Point& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Point unit(Point a) {
  const double l = std::sqrt(dot(a, a));
  for (double& x : a) x /= l;
  return a;
}

// Each vertex of a quad (or triangle) mesh with the faces at which it is a
// corner: the face's (u, v) at that corner.
struct Corner {
  std::size_t face;
  ExactParameter at;
};
std::vector<std::vector<Corner>> corners_of(const Mesh& m, bool triangles = false) {
  std::vector<std::vector<Corner>> out(m.vertex_count());
  std::size_t offset = 0;
  const ExactParameter quad[4] = {grid(0, 0, 1), grid(1, 0, 1), grid(1, 1, 1), grid(0, 1, 1)};
  const ExactParameter triangle[3] = {grid(0, 0, 1), grid(1, 0, 1), grid(0, 1, 1)};
  for (std::size_t f = 0; f < m.face_count(); ++f) {
    if (m.face_sizes[f] == 4 || (triangles && m.face_sizes[f] == 3))
      for (std::size_t c = 0; c < static_cast<std::size_t>(m.face_sizes[f]); ++c)
        out[static_cast<std::size_t>(m.face_vertices[offset + c])].push_back({f, triangles ? triangle[c] : quad[c]});
    offset += static_cast<std::size_t>(m.face_sizes[f]);
  }
  return out;
}


// The normal from the derivatives at distance 2^-k from the corner, into the face.
Point nearby_normal(const Surface& s, const Corner& c, int k, bool triangle = false) {
  const double e = std::ldexp(1.0, -k);
  double u = c.at.u.num == 0 ? e : 1 - e, v = c.at.v.num == 0 ? e : 1 - e;
  if (triangle && c.at.u.num == 1) u = 1 - 2 * e, v = e;  // inside u + v <= 1
  if (triangle && c.at.v.num == 1) u = e, v = 1 - 2 * e;
  return s.derivatives(c.face, u, v).normal();
}

// OpenSubdiv's exact limit tangents at every vertex (Far::PrimvarRefiner::Limit:
// Sdc's limit masks), as unit normals t1 x t2.
std::vector<Point> far_limit_normals(const Mesh& mesh, bfr_reference::osd::Sdc::SchemeType scheme) {
  auto refiner = bfr_reference::make_refiner(static_cast<int>(mesh.vertex_count()), mesh.face_sizes, mesh.face_vertices, scheme);
  std::vector<Primvar> src(mesh.vertex_count()), pos(mesh.vertex_count()), t1(mesh.vertex_count()), t2(mesh.vertex_count());
  for (std::size_t i = 0; i < mesh.vertex_count(); ++i)
    for (int k = 0; k < 3; ++k) src[i].p[k] = mesh.positions[i][static_cast<std::size_t>(k)];
  Primvar *s = src.data(), *p = pos.data(), *a = t1.data(), *b = t2.data();
  bfr_reference::osd::Far::PrimvarRefinerReal<double>(*refiner).Limit(s, p, a, b);
  std::vector<Point> out;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    out.push_back(unit(cross({t1[v].p[0], t1[v].p[1], t1[v].p[2]}, {t2[v].p[0], t2[v].p[1], t2[v].p[2]})));
  return out;
}

// Surface::normal at every extraordinary corner against Far's limit tangents:
// the plane (|n . far| = 1) and the side (the derivatives' normal next to the vertex).
void check_vertex_normals(const Surface& surface, const Mesh& mesh, const std::string& name, bool triangles, double& worst,
                          std::size_t& checked) {
  const std::vector<Point> far =
      far_limit_normals(mesh, triangles ? bfr_reference::osd::Sdc::SCHEME_LOOP : bfr_reference::osd::Sdc::SCHEME_CATMARK);
  const auto corners = corners_of(mesh, triangles);
  const auto valence = vertex_valences(mesh);
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    if (valence[v] == (triangles ? 6 : 4) || corners[v].empty()) continue;
    for (const Corner& c : corners[v]) {
      INFO(name << " vertex " << v << " (valence " << valence[v] << "), face " << c.face << " at " << c.at.str());
      const Point n = surface.normal(c.face, c.at);
      const double e = 1 - std::abs(dot(n, far[v]));
      worst = std::max(worst, e);
      REQUIRE(e < 1e-13);
      REQUIRE(dot(n, nearby_normal(surface, c, 12, triangles)) > 0.99);
      ++checked;
    }
  }
}

}  // namespace

TEST_CASE("Catmull-Clark normals at extraordinary vertices equal OpenSubdiv's exact limit tangents",
          "[runtime][derivatives][opensubdiv]") {
  const auto tables = Tables::load(tables_for("catmull-clark").string());
  double worst = 0;
  std::size_t checked = 0;
  for (const char* name : kBundled) {
    const Mesh mesh = read_obj((kMeshes / (std::string(name) + ".obj")).string());
    const Surface surface = surface_of(tables, mesh);
    check_vertex_normals(surface, mesh, name, false, worst, checked);
  }
  CHECK(checked > 20);
  WARN("largest 1 - |cos| against Far's limit tangents over " << checked << " corners: " << worst);
}

TEST_CASE("normals at extraordinary vertices: the derivatives' normals converge to them, all faces agree, and the "
          "tangent stencils are left eigenvectors of A0",
          "[runtime][derivatives]") {
  for (const char* scheme : {"catmull-clark", "nonpoly"}) {
    const fs::path path = tables_for(scheme);
    const auto tables = Tables::load(path.string());
    // The tangent stencils against an eigen-decomposition in doubles of the tables' A0.
    const QuadTables q = QuadTables::load_binary(path.string());
    for (int valence = 3; valence <= 8; ++valence) {
      if (valence == 4) continue;
      INFO(scheme << " valence " << valence);
      const QuadDescent::Valence& d = q.descent(valence);
      const auto m = static_cast<Eigen::Index>(QuadTables::points(valence));
      REQUIRE(d.tangent_u.size() == static_cast<std::size_t>(m));
      Eigen::MatrixXd a = Eigen::MatrixXd::Zero(m, m);
      for (Eigen::Index r = 0; r < m; ++r)
        for (std::size_t e = d.ev_child.offsets[static_cast<std::size_t>(r)]; e < d.ev_child.offsets[static_cast<std::size_t>(r) + 1]; ++e)
          a(r, static_cast<Eigen::Index>(d.ev_child.columns[e])) = d.ev_child.weights[e];
      Eigen::EigenSolver<Eigen::MatrixXd> solver(a.transpose());
      std::vector<double> moduli;
      for (Eigen::Index i = 0; i < m; ++i) moduli.push_back(std::abs(solver.eigenvalues()(i)));
      std::sort(moduli.rbegin(), moduli.rend());
      CHECK(std::abs(moduli[1] - d.tangent_eigenvalue) < 1e-12);  // the subdominant one
      CHECK(std::abs(moduli[2] - d.tangent_eigenvalue) < 1e-12);  // double
      for (const std::vector<double>* t : {&d.tangent_u, &d.tangent_v}) {
        const Eigen::Map<const Eigen::RowVectorXd> row(t->data(), m);
        const Eigen::RowVectorXd residual = row * a - d.tangent_eigenvalue * row;
        CHECK(residual.cwiseAbs().maxCoeff() < 1e-13 * row.cwiseAbs().maxCoeff());
      }
      // Independent: not parallel.
      const Eigen::Map<const Eigen::VectorXd> tu(d.tangent_u.data(), m), tv(d.tangent_v.data(), m);
      CHECK(std::abs(tu.normalized().dot(tv.normalized())) < 0.999);
    }
    for (const char* name : kBundled) {
      const Mesh mesh = read_obj((kMeshes / (std::string(name) + ".obj")).string());
      const Surface surface = surface_of(tables, mesh);
      const auto corners = corners_of(mesh);
      const auto valence = vertex_valences(mesh);
      for (std::size_t v = 0; v < mesh.vertex_count(); v += 3) {
        if (valence[v] == 4 || corners[v].empty()) continue;
        const Point first = surface.normal(corners[v][0].face, corners[v][0].at);
        for (const Corner& c : corners[v]) {
          INFO(scheme << " " << name << " vertex " << v << " (valence " << valence[v] << "), face " << c.face);
          const Point n = surface.normal(c.face, c.at);
          CHECK(dot(n, first) > 1 - 1e-12);  // every face around the vertex gives the same normal
          if (std::string(scheme) == "nonpoly") continue;  // its derivatives between grids are refused
          // Approaching the vertex the derivatives' normal converges to it.
          const double far = 1 - dot(n, nearby_normal(surface, c, 6)), near = 1 - dot(n, nearby_normal(surface, c, 18));
          CHECK(near < 1e-6);
          CHECK(near <= far);
        }
      }
    }
  }
}

TEST_CASE("Loop normals at extraordinary vertices equal OpenSubdiv's exact limit tangents, and sqrt(3)'s agree round each vertex",
          "[runtime][derivatives][opensubdiv]") {
  const auto loop = Tables::load(generated_table("loop", "--valence 3-8 --n 4", "sgt").string());
  const auto sqrt3 = Tables::load(generated_table("sqrt3", "--valence 3-8 --n 3", "sgt").string());
  double worst = 0;
  std::size_t checked = 0;
  for (const char* name : {"icosahedron", "tri-torus", "tri-mix"}) {
    const Mesh mesh = read_obj((kMeshes / (std::string(name) + ".obj")).string());
    const Surface surface = surface_of(loop, mesh);
    check_vertex_normals(surface, mesh, name, true, worst, checked);
    const auto corners = corners_of(mesh, true);
    const auto valence = vertex_valences(mesh);
    // sqrt(3): no derivatives to compare with, but one normal round each vertex, on the outward side.
    const Surface other = surface_of(sqrt3, mesh);
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
      if (valence[v] == 6 || corners[v].empty()) continue;
      const Point first = other.normal(corners[v][0].face, corners[v][0].at);
      for (const Corner& c : corners[v]) {
        INFO("sqrt3 " << name << " vertex " << v << " (valence " << valence[v] << "), face " << c.face);
        CHECK(dot(other.normal(c.face, c.at), first) > 1 - 1e-12);
      }
      CHECK(dot(first, surface.normal(corners[v][0].face, corners[v][0].at)) > 0.5);  // near Loop's, same side
    }
  }
  CHECK(checked > 20);
  WARN("Loop: largest 1 - |cos| against Far's limit tangents over " << checked << " corners: " << worst);
}
