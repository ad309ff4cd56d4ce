#pragma once
// Coordinates on the neighbourhood of an extraordinary vertex of a triangle
// mesh whose other vertices are regular (valence 6): v sectors, each a 60-degree
// wedge of the triangular lattice of triangle_masks.hpp. Sector k holds the
// points a (1,0) + b (1,1) with a >= 1, 0 <= b < a, in its own frame (its edge
// e_k is (1,0), e_{k+1} is (1,1)); the point (a, a) of sector k is (a, 0) of
// sector k+1. Lattice moves that leave a wedge are carried into the neighbouring
// sector by the 60-degree rotation, so the regular rules can be written once in
// lattice coordinates and applied at every valence.
//
// Points are numbered ring by ring (ring r = hex distance r = a): 0 is the
// extraordinary vertex, then ring r sector k offset b at 1 + v r (r-1)/2 + k r + b.
#include <cstddef>
#include <optional>

namespace sg {

// A lattice point's coordinates carried one 60-degree turn between the frames
// of neighbouring sectors: into sector k-1's (e_k = (1,0) is (1,1) there) and
// into sector k+1's (e_{k+1} = (1,1) is (1,0) there).
inline void into_previous_frame(long& a, long& b) {
  const long na = a - b, nb = a;
  a = na, b = nb;
}
inline void into_next_frame(long& a, long& b) {
  const long na = b, nb = b - a;
  a = na, b = nb;
}

struct SectorPoint {
  int sector = 0;
  long a = 0, b = 0;  // (0, 0) in sector 0 for the extraordinary vertex
  bool operator==(const SectorPoint&) const = default;
};

class SectorChart {
 public:
  SectorChart(int valence, long rings);
  int valence() const { return v_; }
  long rings() const { return rings_; }
  std::size_t size() const { return 1 + static_cast<std::size_t>(v_) * static_cast<std::size_t>(rings_ * (rings_ + 1) / 2); }

  // The lattice point (a, b) of sector k's frame, carried into its own wedge by
  // at most `max_turns` 60-degree turns in the direction it lies; nullopt when
  // more would be needed (a point that far round is not defined by a short path).
  std::optional<SectorPoint> canonical(int k, long a, long b, int max_turns = 2) const;
  // Its number, nullopt when it is not canonical within max_turns or lies
  // beyond the chart's rings.
  std::optional<std::size_t> index(int k, long a, long b, int max_turns = 2) const;
  std::size_t index(const SectorPoint& p) const;
  SectorPoint point(std::size_t id) const;

 private:
  int v_;
  long rings_;
};

}  // namespace sg
