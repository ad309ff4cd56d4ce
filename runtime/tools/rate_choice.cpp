#include "rate_choice.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "stencil_runtime/uniform_topology.hpp"
#include "stencil_runtime/tessellation.hpp"

namespace stencil_tools {

using stencil_runtime::Mesh;

std::vector<int> rates_from_file(const std::string& path, std::size_t faces) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::vector<int> rates;
  std::string line;
  long number = 0;
  while (std::getline(in, line)) {
    ++number;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream ls(line);
    long r = 0;
    if (!(ls >> r)) continue;
    if (r < 1 || r > 4096) throw std::runtime_error(path + ":" + std::to_string(number) + ": rate must be 1..4096");
    rates.push_back(static_cast<int>(r));
  }
  if (rates.size() != faces)
    throw std::runtime_error(path + ": " + std::to_string(rates.size()) + " rates for a mesh of " +
                             std::to_string(faces) + " faces (one per line, in face order)");
  return rates;
}

namespace {
using V = std::array<double, 3>;
V sub(const V& a, const V& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double norm(const V& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
}  // namespace

namespace {

// Second differences along the lattice lines through each corner: the corner's
// next vertex a and the neighbour opposite it (half the valence round), and
// for quads the twist of the face.
template <int K>
std::vector<int> curvature_rates(const Mesh& mesh, double tolerance) {
  using Topology = stencil_runtime::UniformTopology<K>;
  const Topology topo(mesh);
  std::vector<int> rates(topo.faces());
  auto at = [&](int v) -> const V& { return mesh.positions[static_cast<std::size_t>(v)]; };
  auto head = [&](std::uint32_t h) { return topo.vertex(Topology::face_of(h), Topology::corner_of(h) + 1); };
  for (std::size_t f = 0; f < topo.faces(); ++f) {
    double d = 0;
    for (int c = 0; c < K; ++c) {
      const int p = topo.vertex(f, c);
      const std::uint32_t h = Topology::half_edge(f, c);
      std::uint32_t e = h;
      for (int t = 0; t < topo.valence(p) / 2; ++t) e = topo.turn_ccw(e);
      d = std::max(d, norm(sub(sub(at(head(h)), at(p)), sub(at(p), at(head(e))))));
      if constexpr (K == 4) {
        const V skew = sub(sub(at(topo.vertex(f, c + 2)), at(topo.vertex(f, c + 1))), sub(at(topo.vertex(f, c + 3)), at(p)));
        d = std::max(d, norm(skew));
      }
    }
    rates[f] = std::max(1, static_cast<int>(std::ceil(std::sqrt(d / (8 * tolerance)))));
  }
  return rates;
}

}  // namespace

std::vector<int> rates_for_tolerance(const Mesh& mesh, double tolerance, int corners) {
  if (!(tolerance > 0)) throw std::runtime_error("--tolerance must be positive");
  return corners == 3 ? curvature_rates<3>(mesh, tolerance) : curvature_rates<4>(mesh, tolerance);
}

std::vector<int> rates_for_view(const Mesh& mesh, const Camera& cam, double target_pixels) {
  if (!(target_pixels > 0)) throw std::runtime_error("--pixels must be positive");
  const V forward0 = sub(cam.target, cam.eye);
  const double fl = norm(forward0);
  if (fl == 0) throw std::runtime_error("--camera: eye and target coincide");
  const V fwd{forward0[0] / fl, forward0[1] / fl, forward0[2] / fl};
  const double focal = 0.5 * cam.width_pixels / std::tan(0.5 * cam.fov_degrees * M_PI / 180);
  // Pixel length of a short segment at distance depth: focal * length / depth
  // (a conservative, rotation-free projection of each edge).
  std::vector<int> rates(mesh.face_count());
  std::size_t offset = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const int k = mesh.face_sizes[f];
    double longest = 0;
    bool visible = false;
    for (int c = 0; c < k; ++c) {
      const auto& p = mesh.positions[static_cast<std::size_t>(mesh.face_vertices[offset + static_cast<std::size_t>(c)])];
      const auto& q = mesh.positions[static_cast<std::size_t>(mesh.face_vertices[offset + static_cast<std::size_t>((c + 1) % k)])];
      const V mid{(p[0] + q[0]) / 2 - cam.eye[0], (p[1] + q[1]) / 2 - cam.eye[1], (p[2] + q[2]) / 2 - cam.eye[2]};
      const double depth = mid[0] * fwd[0] + mid[1] * fwd[1] + mid[2] * fwd[2];
      if (depth <= 1e-9) continue;
      visible = true;
      longest = std::max(longest, focal * norm(sub(p, q)) / depth);
    }
    rates[f] = visible ? std::max(1, static_cast<int>(std::ceil(longest / target_pixels))) : 1;
    offset += static_cast<std::size_t>(k);
  }
  return rates;
}

void snap_to_tables(std::vector<int>& rates, const std::vector<int>& table_rates) {
  for (int& r : rates) r = stencil_runtime::table_rate_at_least(table_rates, r);
}

}  // namespace stencil_tools
