#pragma once
// The canonical order of the control points of a quad patch (docs/table-format.md).
//
// Extraordinary patch, valence v, extraordinary vertex (EV) at parameter (0,0),
// patch = [0,1]^2. Chart coordinates (i,j) name mesh vertices around the patch as
// in a regular grid: the patch's corners are (0,0), (1,0), (1,1), (0,1).
//   index 0          the EV, chart (0,0)
//   index 1 + 2k     e_k, k = 0..v-1: the EV's edge neighbours, counter-clockwise;
//                    e_0 = (1,0), e_1 = (0,1), e_2 = (-1,0), e_{v-1} = (0,-1)
//   index 2 + 2k     f_k: the vertex opposite the EV in the quad (EV, e_k, f_k, e_{k+1});
//                    f_0 = (1,1), f_1 = (-1,1), f_{v-1} = (1,-1)
//   index 2v+1..2v+7 the outer points (2,-1), (2,0), (2,1), (2,2), (1,2), (0,2), (-1,2)
// For v = 4 every point of the 4x4 block {-1..2}^2 has a chart position
// ((-1,-1) is f_2).
//
// Regular patch: the 16 points (i,j), i,j in {-1..2}, index (j+1)*4 + (i+1);
// the basis of point (i,j) is phi(x - i) phi(y - j).
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace sg {

class PatchLayout {
 public:
  explicit PatchLayout(int valence);
  int valence() const { return v_; }
  std::size_t size() const { return static_cast<std::size_t>(2 * v_ + 8); }
  static std::size_t ev() { return 0; }
  std::size_t edge(int k) const;  // e_{k mod v}
  std::size_t face(int k) const;  // f_{k mod v}
  std::size_t outer(int t) const { return static_cast<std::size_t>(2 * v_ + 1 + t); }
  // Index of chart point (i,j), i,j in {-1..2}; nullopt for (-1,-1) when v != 4.
  std::optional<std::size_t> chart(int i, int j) const;
  // Chart position of every index that has one (one-ring points beyond the
  // patch's neighbours have none).
  std::optional<std::pair<int, int>> position(std::size_t index) const;
  // Index permutation of the reflection (x,y) -> (y,x): W(y,x)[reflect[h]] = W(x,y)[h].
  std::vector<std::size_t> reflection() const;

 private:
  int v_;
};

inline std::size_t regular_index(int i, int j) { return static_cast<std::size_t>((j + 1) * 4 + (i + 1)); }

}  // namespace sg
