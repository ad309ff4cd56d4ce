#pragma once
// A quad mesh around one extraordinary vertex (EV) of valence v, for the
// surface tests. Nothing here calls the generator's solvers; the only link to
// the code under test is the cross-check against sg::PatchLayout in
// check_against_layout().
//
// Topology: v sectors, each a K x K block of quads. Sector s has grid points
// (a,b), 0 <= a,b <= K, and faces (a,b),(a+1,b),(a+1,b+1),(a,b+1)
// (counter-clockwise in the sector's own coordinates). Point (0,b) of sector s
// is the same vertex as point (b,0) of sector s+1 (mod v); the EV is (0,0) of
// every sector. Sector 1's a-axis runs along sector 0's b-axis, so sector 1's
// (a,b) sits at chart (-b,a) of sector 0 (a rotation by +90 degrees), and
// sector v-1's (a,b) sits at chart (b,-a): every face keeps the same
// orientation, and the EV's edge neighbours e_k = sector k's (1,0) run
// counter-clockwise.
//
// The patch under test is sector 0's face (0,0),(1,0),(1,1),(0,1), corners in
// that order: parameter u runs from the EV towards e_0, w towards e_1.
#include <array>
#include <cstdint>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "quad/patch_layout.hpp"

namespace sector_mesh {

class SectorMesh {
 public:
  SectorMesh(int valence, int blocks) : v_(valence), k_(blocks) {
    if (v_ < 3) throw std::invalid_argument("valence must be at least 3");
    if (k_ < 3) throw std::invalid_argument("K must be at least 3 (the patch's one-ring reaches chart distance 2)");
    num_vertices_ = 1 + v_ * k_ * (k_ + 1);
    for (int s = 0; s < v_; ++s)
      for (int b = 0; b < k_; ++b)
        for (int a = 0; a < k_; ++a) {
          if (s == 0 && a == 0 && b == 0) patch_face_ = static_cast<int>(faces_.size());
          faces_.push_back({id(s, a, b), id(s, a + 1, b), id(s, a + 1, b + 1), id(s, a, b + 1)});
        }
    coord_.assign(static_cast<std::size_t>(num_vertices_), std::nullopt);
    for (int a = 0; a <= k_; ++a)
      for (int b = 0; b <= k_; ++b) coord_[static_cast<std::size_t>(id(0, a, b))] = std::array<int, 2>{a, b};
    build_patch_vertices();
  }

  int valence() const { return v_; }
  int blocks() const { return k_; }
  int num_vertices() const { return num_vertices_; }
  const std::vector<std::array<int, 4>>& faces() const { return faces_; }
  // Index into faces() of the patch: corners EV, e_0, f_0, e_1.
  int patch_face() const { return patch_face_; }

  // Vertex id of sector s's grid point (a,b), 0 <= a,b <= K (s taken mod v).
  int id(int s, int a, int b) const {
    s = ((s % v_) + v_) % v_;
    if (a < 0 || b < 0 || a > k_ || b > k_) throw std::out_of_range("sector point out of range");
    if (a == 0 && b == 0) return 0;
    if (a == 0) return id(s + 1, b, 0);  // (0,b) of sector s == (b,0) of sector s+1
    return 1 + s * k_ * (k_ + 1) + (a - 1) * (k_ + 1) + b;
  }

  // Vertex at chart position (i,j) of sector 0's chart: the quadrant i,j >= 0
  // is sector 0 itself, i < 0 <= j lies in sector 1 (its (j,-i)), j < 0 <= i in
  // sector v-1 (its (-j,i)). (-1,-1) exists only at valence 4 (it is f_2).
  int chart_vertex(int i, int j) const {
    if (i >= 0 && j >= 0) return id(0, i, j);
    if (i < 0 && j >= 0) return id(1, j, -i);
    if (j < 0 && i >= 0) return id(v_ - 1, -j, i);
    if (v_ == 4 && i == -1 && j == -1) return id(2, 1, 1);
    throw std::out_of_range("chart point (" + std::to_string(i) + "," + std::to_string(j) + ") has no vertex");
  }

  // Mesh vertex of every canonical patch index (patch_layout.hpp): EV, then
  // e_k, f_k pairs, then the 7 outer points.
  const std::vector<int>& patch_vertices() const { return patch_vertices_; }

  // Chart coordinate (a,b) of every vertex of sector 0's closed quadrant [0,K]^2.
  const std::optional<std::array<int, 2>>& sector0_coord(int vertex) const {
    return coord_[static_cast<std::size_t>(vertex)];
  }

  // Cross-check of the identification with sg::PatchLayout; returns an empty
  // string when consistent, else a description of the first mismatch.
  std::string check_against_layout() const {
    const sg::PatchLayout layout(v_);
    if (layout.size() != patch_vertices_.size()) return "layout size differs from 2v+8";
    for (std::size_t h = 0; h < layout.size(); ++h) {
      const auto pos = layout.position(h);
      if (!pos) continue;
      if (chart_vertex(pos->first, pos->second) != patch_vertices_[h])
        return "index " + std::to_string(h) + " at chart (" + std::to_string(pos->first) + "," +
               std::to_string(pos->second) + ") is not the mesh's vertex there";
    }
    for (int i = -1; i <= 2; ++i)
      for (int j = -1; j <= 2; ++j) {
        const auto h = layout.chart(i, j);
        if (!h) {
          if (!(i == -1 && j == -1 && v_ != 4)) return "layout has no index at chart (" + std::to_string(i) + "," + std::to_string(j) + ")";
          continue;
        }
        if (patch_vertices_[*h] != chart_vertex(i, j))
          return "layout.chart(" + std::to_string(i) + "," + std::to_string(j) + ") names a different vertex";
      }
    // The edge identifications the layout relies on.
    if (chart_vertex(0, 1) != id(1, 1, 0)) return "e_1 = chart (0,1) is not sector 1's (1,0)";
    if (chart_vertex(-1, 0) != id(2, 1, 0)) return "e_2 = chart (-1,0) is not sector 2's (1,0)";
    if (chart_vertex(0, -1) != id(v_ - 1, 1, 0)) return "e_{v-1} = chart (0,-1) is not sector v-1's (1,0)";
    if (chart_vertex(-1, 1) != id(1, 1, 1)) return "f_1 = chart (-1,1) is not sector 1's (1,1)";
    if (chart_vertex(1, -1) != id(v_ - 1, 1, 1)) return "f_{v-1} = chart (1,-1) is not sector v-1's (1,1)";
    // The patch face's corners are EV, e_0, f_0, e_1.
    const auto& f = faces_[static_cast<std::size_t>(patch_face_)];
    if (f[0] != patch_vertices_[layout.ev()] || f[1] != patch_vertices_[layout.edge(0)] ||
        f[2] != patch_vertices_[layout.face(0)] || f[3] != patch_vertices_[layout.edge(1)])
      return "patch face corners are not EV, e_0, f_0, e_1";
    return {};
  }

  // Deterministic random integer coordinates in [-range, range]^3, one per vertex.
  std::vector<std::array<long, 3>> random_integer_points(std::uint32_t seed, long range) const {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<long> d(-range, range);
    std::vector<std::array<long, 3>> p(static_cast<std::size_t>(num_vertices_));
    for (auto& x : p)
      for (auto& c : x) c = d(rng);
    return p;
  }

  // Deterministic random double coordinates in [-1, 1)^3, one per vertex.
  std::vector<std::array<double, 3>> random_points(std::uint32_t seed) const {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> d(-1.0, 1.0);
    std::vector<std::array<double, 3>> p(static_cast<std::size_t>(num_vertices_));
    for (auto& x : p)
      for (auto& c : x) c = d(rng);
    return p;
  }

 private:
  void build_patch_vertices() {
    patch_vertices_.assign(static_cast<std::size_t>(2 * v_ + 8), -1);
    patch_vertices_[0] = id(0, 0, 0);
    for (int k = 0; k < v_; ++k) {
      patch_vertices_[static_cast<std::size_t>(1 + 2 * k)] = id(k, 1, 0);  // e_k
      patch_vertices_[static_cast<std::size_t>(2 + 2 * k)] = id(k, 1, 1);  // f_k
    }
    // Outer points in the documented order (patch_layout.hpp).
    constexpr int outer[7][2] = {{2, -1}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {-1, 2}};
    for (int t = 0; t < 7; ++t)
      patch_vertices_[static_cast<std::size_t>(2 * v_ + 1 + t)] = chart_vertex(outer[t][0], outer[t][1]);
  }

  int v_, k_;
  int num_vertices_ = 0;
  int patch_face_ = -1;
  std::vector<std::array<int, 4>> faces_;
  std::vector<std::optional<std::array<int, 2>>> coord_;
  std::vector<int> patch_vertices_;
};

}  // namespace sector_mesh
