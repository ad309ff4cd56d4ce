// sqrt(3) patches around an extraordinary vertex against plain subdivision: a
// fan mesh is refined 2j times by Kobbelt's rules, written here from the mesh's
// own connectivity (no sector chart), and the fine vertex at each grid node
// (i/3^j, k/3^j) is pushed to the limit with Kobbelt's limit rule
// p + 3 alpha mean(neighbours), over 1 + 3 alpha. The generator's stencil at
// that node must give the same value, in the patch (EV, e_0, e_1) and in the
// three band triangles of the EV's second ring that sqrt(3)'s tables add.
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <tuple>

#include "fan_mesh.hpp"
#include "triangle/triangle_patch.hpp"
#include "triangle/triangle_scheme_loader.hpp"

namespace {

// A point of the cone of v lattice wedges around the EV: sector k, lattice
// coordinates a (1,0) + b (1,1) of its frame, a > 0 and 0 <= b < a (the EV: a = b = 0).
struct ConePoint {
  int sector = 0;
  double a = 0, b = 0;
};
constexpr double kEps = 1e-9;

ConePoint canonical(int v, int k, double a, double b) {
  if (std::fabs(a) < kEps && std::fabs(b) < kEps) return {};
  for (int turn = 0; turn < 6; ++turn) {
    if (a > kEps && b > -kEps && b < a - kEps) return {((k % v) + v) % v, a, std::max(b, 0.0)};
    if (b < -kEps) std::tie(a, b, k) = std::make_tuple(a - b, a, k - 1);  // into sector k-1's frame
    else std::tie(a, b, k) = std::make_tuple(b, b - a, k + 1);            // into sector k+1's frame
  }
  throw std::logic_error("cone point does not settle");
}

// The centroid of a small triangle: its corners brought into one sector's frame.
ConePoint centroid(int v, const ConePoint& p, const ConePoint& q, const ConePoint& r) {
  const ConePoint* frame = p.a > 0 ? &p : q.a > 0 ? &q : &r;
  const int s = frame->sector;
  double a = 0, b = 0;
  for (const ConePoint* c : {&p, &q, &r}) {
    double ca = c->a, cb = c->b;
    if (c->a > 0 && c->sector != s) {
      if ((c->sector + 1) % v == s) std::tie(ca, cb) = std::make_pair(cb, cb - ca);       // from sector s-1
      else if ((s + 1) % v == c->sector) std::tie(ca, cb) = std::make_pair(ca - cb, ca);  // from sector s+1
      else throw std::logic_error("triangle spans more than three sectors");
    }
    a += ca / 3, b += cb / 3;
  }
  return canonical(v, s, a, b);
}

struct Mesh {
  std::vector<double> value;                 // the scalar being subdivided
  std::vector<ConePoint> pos;                // where each vertex sits on the cone around the EV
  std::vector<std::array<int, 3>> triangles; // counter-clockwise
};

double alpha(int valence) { return (4 - 2 * std::cos(2 * M_PI / valence)) / 9; }

std::vector<std::set<int>> neighbours(const Mesh& m) {
  std::vector<std::set<int>> n(m.value.size());
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) n[t[k]].insert({t[(k + 1) % 3], t[(k + 2) % 3]});
  return n;
}

// One sqrt(3) step; boundary vertices keep their values (the band they spoil
// stays far from the patch).
Mesh sqrt3_step(const Mesh& m, int v) {
  const auto nb = neighbours(m);
  std::map<std::pair<int, int>, int> edge_faces;  // directed edge -> face
  for (std::size_t f = 0; f < m.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) edge_faces[{m.triangles[f][k], m.triangles[f][(k + 1) % 3]}] = static_cast<int>(f);
  std::vector<char> boundary(m.value.size(), 0);
  for (const auto& [e, f] : edge_faces)
    if (!edge_faces.count({e.second, e.first})) boundary[e.first] = boundary[e.second] = 1;
  Mesh out;
  for (std::size_t p = 0; p < m.value.size(); ++p) {
    double x = m.value[p];
    if (!boundary[p]) {
      const double a = alpha(static_cast<int>(nb[p].size()));
      double sum = 0;
      for (int q : nb[p]) sum += m.value[q];
      x = (1 - a) * x + a * sum / static_cast<double>(nb[p].size());
    }
    out.value.push_back(x);
    out.pos.push_back(m.pos[p]);
  }
  const int first_face = static_cast<int>(out.value.size());
  for (const auto& t : m.triangles) {
    out.value.push_back((m.value[t[0]] + m.value[t[1]] + m.value[t[2]]) / 3);
    out.pos.push_back(centroid(v, m.pos[t[0]], m.pos[t[1]], m.pos[t[2]]));
  }
  for (const auto& [e, f] : edge_faces) {
    const auto twin = edge_faces.find({e.second, e.first});
    if (twin == edge_faces.end()) {
      out.triangles.push_back({e.first, e.second, first_face + f});
    } else if (e.first < e.second) {  // the flipped edge: two new triangles
      out.triangles.push_back({e.first, first_face + twin->second, first_face + f});
      out.triangles.push_back({e.second, first_face + f, first_face + twin->second});
    }
  }
  return out;
}

template <class T>
void check_valence(const sg::TriangleScheme& sqrt3, int v) {
  FanMesh fan(v, 9);
  Mesh mesh;
  std::mt19937 rng(77u + static_cast<unsigned>(v));
  std::uniform_real_distribution<double> U(-1, 1);
  mesh.value.resize(static_cast<std::size_t>(fan.count));
  for (double& x : mesh.value) x = U(rng);
  mesh.pos.resize(mesh.value.size());
  for (const auto& [key, id] : fan.id) mesh.pos[static_cast<std::size_t>(id)] = {key[0], double(key[1]), double(key[2])};
  for (std::size_t t = 0; t + 2 < fan.triangles.size(); t += 3)
    mesh.triangles.push_back({fan.triangles[t], fan.triangles[t + 1], fan.triangles[t + 2]});

  const std::vector<double> control = mesh.value;
  long n = 1;
  for (int j = 1; j <= 2; ++j) {
    mesh = sqrt3_step(sqrt3_step(mesh, v), v);
    n *= 3;
    const auto nb = neighbours(mesh);
    // Region corners in sector 0's frame (a, b), written out here as the
    // tables document them: the patch, then the band.
    static constexpr long corners[4][3][2] = {{{0, 0}, {1, 0}, {1, 1}},
                                              {{1, 0}, {2, 0}, {2, 1}},
                                              {{1, 0}, {2, 1}, {1, 1}},
                                              {{1, 1}, {2, 1}, {2, 2}}};
    const int regions = v == 6 ? 1 : 4;
    REQUIRE(sg::patch_regions(sqrt3, v) == regions);
    std::vector<std::array<long, 3>> band;
    for (long r = 1; r < regions; ++r)
      for (long k = 0; k <= n; ++k)
        for (long i = 0; i + k <= n; ++i) band.push_back({r, i, k});
    const auto patch = sg::solve_triangle_patch<T>(sqrt3, v, n, sg::solve_regular(sqrt3, n), band);
    for (int r = 0; r < regions; ++r)
    for (long k = 0; k <= n; ++k)
      for (long i = 0; i + k <= n; ++i) {
        const auto& c = corners[r];
        const double u = double(i) / n, w = double(k) / n;
        const ConePoint target = canonical(v, 0, c[0][0] + u * (c[1][0] - c[0][0]) + w * (c[2][0] - c[0][0]),
                                           c[0][1] + u * (c[1][1] - c[0][1]) + w * (c[2][1] - c[0][1]));
        int found = -1;
        for (std::size_t p = 0; p < mesh.value.size(); ++p) {
          const ConePoint& c = mesh.pos[p];
          if (c.sector == target.sector && std::fabs(c.a - target.a) < kEps && std::fabs(c.b - target.b) < kEps) {
            REQUIRE(found == -1);
            found = static_cast<int>(p);
          }
        }
        INFO("valence " << v << ", n = " << n << ", region " << r << ", node (" << i << "," << k << ")");
        REQUIRE(found >= 0);
        const double a = alpha(static_cast<int>(nb[found].size()));
        double mean = 0;
        for (int q : nb[found]) mean += mesh.value[q];
        mean /= static_cast<double>(nb[found].size());
        const double limit = (mesh.value[found] + 3 * a * mean) / (1 + 3 * a);
        double ours = 0;
        for (const auto& [h, x] : patch.at(r, i, k)) ours += sg::to_double(x) * control[static_cast<std::size_t>(fan.at(patch.chart.point(h)))];
        REQUIRE(std::fabs(ours - limit) < 1e-12);
      }
  }
}

}  // namespace

TEST_CASE("sqrt(3) patches and band triangles equal 2j steps of plain subdivision and the limit rule at n = 3, 9",
          "[triangle][sqrt3]") {
  const sg::TriangleScheme sqrt3 = sg::load_triangle_scheme("sqrt3");
  for (int v : {3, 4, 5, 6, 7, 8, 12}) {
    if (sqrt3.exact_neighbour_weight(v)) check_valence<sg::Rational>(sqrt3, v);
    else check_valence<sg::Real>(sqrt3, v);
  }
}
