#pragma once
// A triangle fan around one extraordinary vertex for the tests: v triangular
// sectors of side K, built from plain vertex and triangle lists (no code shared
// with the generator's sector chart).
#include <array>
#include <map>
#include <vector>

#include "triangle/sector_chart.hpp"

// v triangular sectors of side K around the EV. Sector s holds (a, b),
// 0 <= b <= a <= K, with (a, 0) on the ray of e_s and (a, a) on the ray of
// e_{s+1}; (a, a) of sector s is (a, 0) of sector s+1.
struct FanMesh {
  int v, K;
  std::map<std::array<int, 3>, int> id;  // (sector, a, b) -> vertex
  int count = 0;
  std::vector<int> triangles;
  FanMesh(int valence, int rings) : v(valence), K(rings) {
    for (int s = 0; s < v; ++s)
      for (int a = 0; a <= K; ++a)
        for (int b = 0; b <= a; ++b) vertex(s, a, b);
    for (int s = 0; s < v; ++s)
      for (int a = 0; a < K; ++a)
        for (int b = 0; b <= a; ++b) {
          triangles.insert(triangles.end(), {vertex(s, a, b), vertex(s, a + 1, b), vertex(s, a + 1, b + 1)});
          if (b + 1 <= a) triangles.insert(triangles.end(), {vertex(s, a, b), vertex(s, a + 1, b + 1), vertex(s, a, b + 1)});
        }
  }
  int vertex(int s, int a, int b) {
    s = ((s % v) + v) % v;
    if (a == 0) return key({0, 0, 0});
    if (b == a) return vertex(s + 1, a, 0);
    return key({s, a, b});
  }
  int key(std::array<int, 3> k) {
    const auto it = id.find(k);
    if (it != id.end()) return it->second;
    id[k] = count;
    return count++;
  }
  // The mesh vertex of a sector-chart point.
  int at(const sg::SectorPoint& p) { return vertex(p.sector, static_cast<int>(p.a), static_cast<int>(p.b)); }
};
