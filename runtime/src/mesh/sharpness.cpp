#include "sharpness.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "stencil_runtime/error.hpp"

namespace stencil_runtime {

namespace {

// A sharpness of 10 or more is infinite (OpenSubdiv's SHARPNESS_INFINITE), kept as 10.
float checked(double s, const std::string& what, bool infinite_allowed) {
  if (!std::isfinite(s) || s < 0)
    throw MeshError(what + " has sharpness " + number_text(s) + "; a sharpness is a finite number >= 0");
  if (s >= kInfiniteSharpness && !infinite_allowed)
    throw MeshError(what + " has sharpness " + number_text(s) +
                    ", which OpenSubdiv treats as infinitely sharp (>= 10); infinitely sharp creases and corners are made "
                    "for quad schemes only so far: give it a finite sharpness below 10");
  return std::min(static_cast<float>(s), kInfiniteSharpness);
}

bool semi_sharp(float s) { return s > 0 && s < kInfiniteSharpness; }

}  // namespace

LevelSharpness LevelSharpness::of(const Connectivity& mesh, const MeshFeatures& features, bool infinite_allowed) {
  LevelSharpness out;
  out.chaikin_ = features.chaikin;
  if (features.edges.empty() && features.vertices.empty()) return out;  // the common case: nothing to look up
  std::set<std::pair<int, int>> edges;
  std::size_t corner = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const std::size_t k = static_cast<std::size_t>(mesh.face_sizes[f]);
    for (std::size_t c = 0; c < k; ++c)
      edges.insert(key(mesh.face_vertices[corner + c], mesh.face_vertices[corner + (c + 1) % k]));
    corner += k;
  }
  for (const auto& e : features.edges) {
    const std::string what = "the crease on the edge " + std::to_string(e.a) + "-" + std::to_string(e.b);
    if (!edges.count(key(e.a, e.b))) throw MeshError(what + " names no edge of the mesh");
    const float s = checked(e.sharpness, what, infinite_allowed);
    if (s > 0) out.edges_[key(e.a, e.b)] = s;
    else out.edges_.erase(key(e.a, e.b));
  }
  for (const auto& v : features.vertices) {
    const std::string what = "the corner at vertex " + std::to_string(v.vertex);
    if (v.vertex < 0 || static_cast<std::size_t>(v.vertex) >= mesh.vertex_count)
      throw MeshError(what + " names no vertex (the mesh has " + std::to_string(mesh.vertex_count) + ")");
    const float s = checked(v.sharpness, what, infinite_allowed);
    if (s > 0) out.vertices_[v.vertex] = s;
    else out.vertices_.erase(v.vertex);
  }
  return out;
}

float LevelSharpness::edge(int a, int b) const {
  const auto it = edges_.find(key(a, b));
  return it == edges_.end() ? 0.0f : it->second;
}

float LevelSharpness::vertex(int v) const {
  const auto it = vertices_.find(v);
  return it == vertices_.end() ? 0.0f : it->second;
}

float LevelSharpness::max() const {
  float m = 0;
  for (const auto& [e, s] : edges_)
    if (semi_sharp(s)) m = std::max(m, s);
  for (const auto& [v, s] : vertices_)
    if (semi_sharp(s)) m = std::max(m, s);
  return m;
}

bool LevelSharpness::infinite() const {
  for (const auto& [e, s] : edges_)
    if (!semi_sharp(s)) return true;
  for (const auto& [v, s] : vertices_)
    if (!semi_sharp(s)) return true;
  return false;
}

void LevelSharpness::set_edge(int a, int b, float s) {
  if (s > 0) edges_[key(a, b)] = s;
}

void LevelSharpness::set_vertex(int v, float s) {
  if (s > 0) vertices_[v] = s;
}

CreaseRule crease_rule(float vertex_sharpness, const float* edges, std::size_t n) {
  if (vertex_sharpness > 0) return CreaseRule::Corner;
  std::size_t sharp = 0;
  for (std::size_t i = 0; i < n; ++i) sharp += edges[i] > 0;
  switch (sharp) {
    case 0: return CreaseRule::Smooth;
    case 1: return CreaseRule::Dart;
    case 2: return CreaseRule::Crease;
    default: return CreaseRule::Corner;
  }
}

float decayed_sharpness(float s) {
  if (s <= 0) return 0;
  if (s >= kInfiniteSharpness) return kInfiniteSharpness;
  return s > 1.0f ? s - 1.0f : 0.0f;
}

float child_edge_sharpness(std::size_t i, const float* edges, std::size_t n, bool chaikin) {
  const float s = edges[i];
  if (!chaikin || n < 2) return decayed_sharpness(s);
  if (s <= 0) return 0;
  if (s >= kInfiniteSharpness) return kInfiniteSharpness;
  float sum = 0;
  int count = 0;
  for (std::size_t k = 0; k < n; ++k)
    if (semi_sharp(edges[k])) {
      ++count;
      sum += edges[k];
    }
  float child = s;
  // Chaikin: three quarters of its own sharpness and a quarter of the others' mean.
  if (count > 1) child = 0.75f * s + 0.25f * ((sum - s) / static_cast<float>(count - 1));
  child -= 1.0f;
  return child > 0 ? child : 0.0f;
}

float transition_weight(float parent_vertex, float child_vertex, const float* parent_edges, const float* child_edges,
                        std::size_t n, bool chaikin) {
  int count = 0;
  float sum = 0;
  if (parent_vertex > 0 && child_vertex <= 0) {
    count = 1;
    sum = parent_vertex;
  }
  for (std::size_t i = 0; i < n; ++i) {
    // Uniform decay ends exactly the edges of sharpness <= 1; Chaikin's must be looked at.
    const bool ends = chaikin ? parent_edges[i] > 0 && child_edges[i] <= 0 : parent_edges[i] > 0 && parent_edges[i] <= 1.0f;
    if (ends) {
      sum += parent_edges[i];
      ++count;
    }
  }
  if (count == 0) return 0;
  const float w = sum / static_cast<float>(count);
  return w > 1.0f ? 1.0f : w;
}

}  // namespace stencil_runtime
