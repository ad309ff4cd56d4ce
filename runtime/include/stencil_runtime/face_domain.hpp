#pragma once
// What (u, v) means on a face, as OpenSubdiv's Bfr::Parameterization defines it:
//  - Quad: a quad face of a quad scheme; (0,0) at its first vertex v0, u along
//    v0->v1, v along v0->v3, (u, v) in [0,1]^2.
//  - Triangle: a triangle of a triangle scheme; u along v0->v1, v along v0->v2,
//    u, v >= 0, u + v <= 1.
//  - QuadSubfaces: an N-gon (N != 4) of a quad scheme, whose surface is that of
//    the N quads of the scheme's polygon step. Sub-face s (the quad at corner s)
//    is the tile [s % U, s % U + 1/2] x [s / U, s / U + 1/2], U = u_tiles (2 for
//    N = 3, 3 for 5 <= N <= 9, 1 + floor(sqrt(N - 1)) above); within it,
//    (u - s % U, v - s / U) times 2 is the sub-face's own (u, v): 0 at corner s,
//    u towards the middle of edge s -> s+1, v towards the middle of edge s -> s-1,
//    (1, 1) at the face's centre.
#include <cstdint>
#include <string>

#include "exact_parameter.hpp"
#include "tables.hpp"

namespace stencil_runtime {

struct FaceDomain {
  enum class Kind { Quad, Triangle, QuadSubfaces };
  Kind kind = Kind::Quad;
  int corners = 4;  // the face's size
  int u_tiles = 1;  // QuadSubfaces: sub-faces per row (Bfr's "uDim")

  // The domain of a face with `corners` corners under a scheme family; throws
  // MeshError when the family cannot parameterize it (a triangle scheme on a
  // face that is not a triangle).
  static FaceDomain of(SchemeFamily family, int corners);

  // Whether (u, v) lies in the domain (tiles include their edges).
  bool contains(double u, double v) const;
  bool contains(const ExactParameter& p) const;
  // Moves (u, v) to the nearest point of the domain (within the sub-face that
  // subface() picks for an N-gon): for a parameter computed from another,
  // which rounding may leave just outside (NaN stays NaN).
  void clamp(double& u, double& v) const;
  // QuadSubfaces: the sub-face holding (u, v) (Bfr's rule: points on a tile's
  // border go to the tile whose lower-left is nearer) and its own coordinates.
  // For (u, v) outside the domain, the nearest tile's (coordinates outside
  // [0, 1]); NaN counts as 0 there. The exact one throws ParameterOverflow
  // where the sub-face's coordinates do not fit in 64-bit fractions.
  int subface(double u, double v, double& su, double& sv) const;
  int subface(const ExactParameter& p, ExactParameter& local) const;
  // A description for error messages, e.g. "[0,1]^2" or "u, v >= 0, u + v <= 1".
  const char* describe() const;
  // The message for a parameter outside face `face`'s domain, the parameter
  // written with every digit it has (a %f "-0.000000" would hide why).
  std::string outside(std::size_t face, double u, double v) const;
  std::string outside(std::size_t face, const ExactParameter& at) const;

 private:
  std::string outside_text(std::size_t face, const std::string& at) const;
  // The tile (sub-face column and row) of floor(u + 1/4), floor(v + 1/4).
  void tiles(std::int64_t u_floor, std::int64_t v_floor, std::int64_t& ut, std::int64_t& vt) const;
};

// "(u, v)" with every digit each has (%.17g), as messages write a real parameter.
std::string parameter_text(double u, double v);

}  // namespace stencil_runtime
