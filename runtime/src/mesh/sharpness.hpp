#pragma once
// The sharpness of one mesh level under OpenSubdiv's creasing rules
// (Sdc::Crease): which rule a vertex follows, the weight of a transition
// between rules, and the sharpness of the next level. Values are kept in
// float, as OpenSubdiv keeps them, so that decay and Chaikin's averaging round
// as they do there and both give the same surface.
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

#include "connectivity.hpp"
#include "stencil_runtime/mesh.hpp"

namespace stencil_runtime {

enum class CreaseRule { Smooth, Dart, Crease, Corner };

// OpenSubdiv's infinite sharpness: a feature this sharp never decays.
inline constexpr float kInfiniteSharpness = 10.0f;

class LevelSharpness {
 public:
  LevelSharpness() = default;
  // The features on `mesh` (closed, already linked). Throws MeshError for an
  // edge that is not an edge of the mesh, a vertex that does not exist, a
  // sharpness that is negative or not finite, and, unless `infinite_allowed`,
  // an infinitely sharp one (>= 10, kept as 10). A feature given twice takes
  // its last value.
  static LevelSharpness of(const Connectivity& mesh, const MeshFeatures& features, bool infinite_allowed = false);

  bool chaikin() const { return chaikin_; }
  bool smooth() const { return edges_.empty() && vertices_.empty(); }
  // Whether a semi-sharp feature is left (infinitely sharp ones never decay).
  bool has_semi_sharp() const { return max() > 0; }
  bool infinite() const;  // whether an infinitely sharp feature is there
  float edge(int a, int b) const;
  float vertex(int v) const;
  float max() const;  // the largest semi-sharp sharpness left (0 when none)

  // Calls f(a, b, s) for each sharp edge (a < b) and g(v, s) for each sharp vertex.
  template <class F>
  void for_each_edge(F&& f) const {
    for (const auto& [e, s] : edges_) f(e.first, e.second, s);
  }
  template <class G>
  void for_each_vertex(G&& g) const {
    for (const auto& [v, s] : vertices_) g(v, s);
  }

  void set_edge(int a, int b, float s);  // ignored unless s > 0
  void set_vertex(int v, float s);       // ignored unless s > 0
  LevelSharpness empty_like() const {
    LevelSharpness out;
    out.chaikin_ = chaikin_;
    return out;
  }

 private:
  static std::pair<int, int> key(int a, int b) { return a < b ? std::pair{a, b} : std::pair{b, a}; }
  std::map<std::pair<int, int>, float> edges_;  // only the sharp ones
  std::map<int, float> vertices_;
  bool chaikin_ = false;
};

// The rules of Sdc::Crease, for a vertex with `n` incident edges of sharpness `edges`:
CreaseRule crease_rule(float vertex_sharpness, const float* edges, std::size_t n);
// One step's decay of a vertex's sharpness (and of an edge's, uniform method).
float decayed_sharpness(float s);
// The sharpness of the child of edge `i` at the vertex with incident sharpness `edges`.
float child_edge_sharpness(std::size_t i, const float* edges, std::size_t n, bool chaikin);
// The weight of the parent's mask where the vertex's rule changes from one level to the next.
float transition_weight(float parent_vertex, float child_vertex, const float* parent_edges, const float* child_edges,
                        std::size_t n, bool chaikin);

}  // namespace stencil_runtime
