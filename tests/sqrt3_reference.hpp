#pragma once
// Plain sqrt(3) subdivision of a closed triangle mesh for the runtime tests,
// written from Kobbelt's paper and nothing of the runtime: relax every old
// vertex with alpha(v) = (4 - 2 cos(2 pi / v)) / 9, insert each face's
// centroid, flip the old edges. Each vertex also carries where it lies on the
// original mesh: every original face that holds it, with integer barycentric
// weights over that face's corners (summing to kDenominator). A new vertex is
// the centroid of three vertices, so its place is their mean, taken in the
// frame of an original face they share or, for a vertex of the one
// neighbouring face the three straddle, after unfolding that face across the
// shared edge into the plane.
// After 2j steps the vertex at parameter (i/3^j, k/3^j) of an original face is
// looked up by those weights, and Kobbelt's limit rule gives its limit point.
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <vector>

#include "stencil_runtime/mesh.hpp"

namespace sqrt3_reference {

constexpr long kDenominator = 729;  // 3^6: exact for up to six steps

struct Place {
  int face;
  std::array<long, 3> w;  // weights of the original face's corners 0, 1, 2
};

class Subdivision {
 public:
  explicit Subdivision(const stencil_runtime::Mesh& mesh) : positions_(mesh.positions) {
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      if (mesh.face_sizes[f] != 3) throw std::invalid_argument("not a triangle mesh");
      const std::array<int, 3> t{mesh.face_vertices[3 * f], mesh.face_vertices[3 * f + 1], mesh.face_vertices[3 * f + 2]};
      original_.push_back(t);
      triangles_.push_back(t);
    }
    places_.resize(positions_.size());
    for (std::size_t f = 0; f < original_.size(); ++f)
      for (int c = 0; c < 3; ++c) {
        Place p{static_cast<int>(f), {0, 0, 0}};
        p.w[static_cast<std::size_t>(c)] = kDenominator;
        places_[static_cast<std::size_t>(original_[f][static_cast<std::size_t>(c)])].push_back(p);
      }
    std::map<std::pair<int, int>, int> face_of_edge;
    for (std::size_t f = 0; f < original_.size(); ++f)
      for (int c = 0; c < 3; ++c) face_of_edge[{original_[f][c], original_[f][(c + 1) % 3]}] = static_cast<int>(f);
    for (std::size_t f = 0; f < original_.size(); ++f)
      for (int c = 0; c < 3; ++c) across_[{static_cast<int>(f), face_of_edge.at({original_[f][(c + 1) % 3], original_[f][c]})}] = c;
  }

  static double alpha(int valence) { return (4 - 2 * std::cos(2 * M_PI / valence)) / 9; }

  void step() {
    const std::vector<std::set<int>> nb = neighbours();
    std::vector<std::array<double, 3>> next(positions_.size());
    for (std::size_t p = 0; p < positions_.size(); ++p) {
      const double a = alpha(static_cast<int>(nb[p].size()));
      for (int k = 0; k < 3; ++k) {
        double mean = 0;
        for (int q : nb[p]) mean += positions_[static_cast<std::size_t>(q)][k];
        next[p][k] = (1 - a) * positions_[p][k] + a * mean / static_cast<double>(nb[p].size());
      }
    }
    const int first_centre = static_cast<int>(positions_.size());
    for (const auto& t : triangles_) {
      std::array<double, 3> c{0, 0, 0};
      for (int v : t)
        for (int k = 0; k < 3; ++k) c[k] += positions_[static_cast<std::size_t>(v)][k] / 3;
      next.push_back(c);
      places_.push_back(centroid_places(t));
    }
    std::map<std::pair<int, int>, int> face_of_edge;
    for (std::size_t f = 0; f < triangles_.size(); ++f)
      for (int c = 0; c < 3; ++c) face_of_edge[{triangles_[f][c], triangles_[f][(c + 1) % 3]}] = static_cast<int>(f);
    std::vector<std::array<int, 3>> flipped;
    for (const auto& [edge, f] : face_of_edge) {
      if (edge.first > edge.second) continue;
      const int g = face_of_edge.at({edge.second, edge.first});
      flipped.push_back({edge.first, first_centre + g, first_centre + f});
      flipped.push_back({edge.second, first_centre + f, first_centre + g});
    }
    positions_ = std::move(next);
    triangles_ = std::move(flipped);
  }

  // Kobbelt's limit position of every vertex: (p + 3 alpha mean) / (1 + 3 alpha).
  std::vector<std::array<double, 3>> limits() const {
    const std::vector<std::set<int>> nb = neighbours();
    std::vector<std::array<double, 3>> out(positions_.size());
    for (std::size_t p = 0; p < positions_.size(); ++p) {
      const double a = alpha(static_cast<int>(nb[p].size()));
      for (int c = 0; c < 3; ++c) {
        double mean = 0;
        for (int x : nb[p]) mean += positions_[static_cast<std::size_t>(x)][c];
        mean /= static_cast<double>(nb[p].size());
        out[p][c] = (positions_[p][c] + 3 * a * mean) / (1 + 3 * a);
      }
    }
    return out;
  }

  // The vertex at (i/n, k/n) of original face f (u along corner 0 -> 1, v
  // along 0 -> 2); n must divide kDenominator and the mesh must have been
  // refined to that lattice (2j steps for n = 3^j).
  int vertex_at(int f, long i, long k, long n) const {
    if (indexed_ != positions_.size()) {
      lookup_.clear();
      for (std::size_t p = 0; p < places_.size(); ++p)
        for (const Place& q : places_[p])
          if (!lookup_.emplace(std::array<long, 3>{q.face, q.w[1], q.w[2]}, static_cast<int>(p)).second)
            throw std::logic_error("two vertices at one place");
      indexed_ = positions_.size();
    }
    const long s = kDenominator / n;
    const auto it = lookup_.find({f, s * i, s * k});
    if (it == lookup_.end()) throw std::logic_error("no vertex at that parameter");
    return it->second;
  }

  std::size_t vertices() const { return positions_.size(); }

 private:
  std::vector<std::set<int>> neighbours() const {
    std::vector<std::set<int>> n(positions_.size());
    for (const auto& t : triangles_)
      for (int k = 0; k < 3; ++k) n[static_cast<std::size_t>(t[k])].insert({t[(k + 1) % 3], t[(k + 2) % 3]});
    return n;
  }

  // A place in original face f's frame: as it is when on f, unfolded across
  // the shared edge when on a neighbour of f.
  std::optional<std::array<long, 3>> in_frame(int f, const Place& p) const {
    if (p.face == f) return p.w;
    const auto it = across_.find({f, p.face});
    if (it == across_.end()) return std::nullopt;
    const int c = it->second;  // f's edge c -> c+1 is shared; f's corner c+2 is opposite
    const auto& F = original_[static_cast<std::size_t>(f)];
    const auto& G = original_[static_cast<std::size_t>(p.face)];
    std::array<long, 3> out{0, 0, 0};
    long far = 0;  // weight of G's corner off the shared edge
    for (int g = 0; g < 3; ++g) {
      if (G[g] == F[c]) out[static_cast<std::size_t>(c)] += p.w[g];
      else if (G[g] == F[(c + 1) % 3]) out[static_cast<std::size_t>((c + 1) % 3)] += p.w[g];
      else far = p.w[g];
    }
    // In the plane, G's far corner sits at F[c] + F[c+1] - F[c+2].
    out[static_cast<std::size_t>(c)] += far;
    out[static_cast<std::size_t>((c + 1) % 3)] += far;
    out[static_cast<std::size_t>((c + 2) % 3)] -= far;
    return out;
  }

  // A new vertex is the centroid of a triangle t that lies in one original
  // face or straddles one edge between two, f and g; then its corners off f
  // are inside g (face centres). Its place in f's frame: the mean of its
  // corners' places, those inside g unfolded across the shared edge.
  std::vector<Place> centroid_places(const std::array<int, 3>& t) const {
    std::set<int> faces;
    for (int v : t)
      for (const Place& p : places_[static_cast<std::size_t>(v)]) faces.insert(p.face);
    std::vector<Place> out;
    for (int f : faces)
      for (int g : faces) {
        if (g != f && !across_.count({f, g})) continue;
        std::array<long, 3> sum{0, 0, 0};
        bool all = true;
        for (int v : t) {
          // On f as it is; unfolded only from inside g (a corner of g that is
          // not on f also lies on other faces, and g may not be its home).
          std::optional<std::array<long, 3>> w;
          const auto& places = places_[static_cast<std::size_t>(v)];
          for (const Place& p : places)
            if (p.face == f) w = p.w;
          if (!w && places.size() == 1 && places.front().face == g) w = in_frame(f, places.front());
          if (!w) {
            all = false;
            break;
          }
          for (int k = 0; k < 3; ++k) sum[k] += (*w)[k];
        }
        if (!all || sum[0] < 0 || sum[1] < 0 || sum[2] < 0) continue;
        if (sum[0] % 3 || sum[1] % 3 || sum[2] % 3) throw std::logic_error("more steps than kDenominator resolves");
        const Place place{f, {sum[0] / 3, sum[1] / 3, sum[2] / 3}};
        bool known = false;
        for (const Place& q : out) known = known || (q.face == place.face && q.w == place.w);
        if (!known) out.push_back(place);
      }
    if (out.empty()) throw std::logic_error("a new vertex lies on no original face");
    return out;
  }

  std::vector<std::array<double, 3>> positions_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<std::vector<Place>> places_;
  std::vector<std::array<int, 3>> original_;
  std::map<std::pair<int, int>, int> across_;  // (face, neighbour) -> the face's shared edge
  mutable std::size_t indexed_ = 0;                    // lookup_ covers this many vertices
  mutable std::map<std::array<long, 3>, int> lookup_;  // (face, w1, w2) -> vertex
};

}  // namespace sqrt3_reference
