#include "stencil_runtime/face_domain.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "stencil_runtime/limits.hpp"

namespace stencil_runtime {

namespace {

// Bfr's tiling of an N-gon's sub-faces: the integer square root of N keeps the tiles accurate.
int u_tiles_for(int corners) {
  return corners < 10 ? 2 + (corners > 4) : 1 + static_cast<int>(std::sqrt(static_cast<double>(corners - 1)));
}

}  // namespace

FaceDomain FaceDomain::of(SchemeFamily family, int corners) {
  if (corners < 3 || corners > limits::kMaxFaceSize)
    throw MeshError("a face of " + std::to_string(corners) + " vertices (faces have 3.." + std::to_string(limits::kMaxFaceSize) + ")");
  if (family == SchemeFamily::Triangle) {
    if (corners != 3) throw MeshError("a face of " + std::to_string(corners) + " vertices: triangle schemes need a mesh of triangles");
    return {Kind::Triangle, 3, 1};
  }
  if (corners == 4) return {Kind::Quad, 4, 1};
  return {Kind::QuadSubfaces, corners, u_tiles_for(corners)};
}

const char* FaceDomain::describe() const {
  switch (kind) {
    case Kind::Quad: return "0 <= u, v <= 1";
    case Kind::Triangle: return "u, v >= 0 and u + v <= 1";
    default: return "the tiles of its sub-faces (sub-face s: [s % U, s % U + 1/2] x [s / U, s / U + 1/2])";
  }
}

std::string parameter_text(double u, double v) {
  char text[64];
  std::snprintf(text, sizeof text, "(%.17g, %.17g)", u, v);
  return text;
}

std::string FaceDomain::outside(std::size_t face, double u, double v) const {
  return outside_text(face, parameter_text(u, v));
}

std::string FaceDomain::outside(std::size_t face, const ExactParameter& at) const { return outside_text(face, at.str()); }

std::string FaceDomain::outside_text(std::size_t face, const std::string& at) const {
  return "the parameter " + at + " lies outside face " + std::to_string(face) + " (its domain is " + describe() + ")";
}

bool FaceDomain::contains(double u, double v) const {
  if (!(u >= 0) || !(v >= 0)) return false;  // also refuses NaN
  switch (kind) {
    case Kind::Quad: return u <= 1 && v <= 1;
    case Kind::Triangle: return u + v <= 1;
    default: {
      double su = 0, sv = 0;
      subface(u, v, su, sv);
      return su >= 0 && sv >= 0 && su <= 1 && sv <= 1;
    }
  }
}

bool FaceDomain::contains(const ExactParameter& p) const {
  const Fraction zero{0, 1}, one{1, 1};
  if (compare(p.u, zero) < 0 || compare(p.v, zero) < 0) return false;
  switch (kind) {
    case Kind::Quad: return compare(p.u, one) <= 0 && compare(p.v, one) <= 0;
    case Kind::Triangle: return compare(add(p.u, p.v), one) <= 0;
    default: {
      ExactParameter local;
      subface(p, local);
      return compare(local.u, zero) >= 0 && compare(local.v, zero) >= 0 && compare(local.u, one) <= 0 &&
             compare(local.v, one) <= 0;
    }
  }
}

int FaceDomain::subface(double u, double v, double& su, double& sv) const {
  // Bfr's rule: a point within 1/4 beyond a tile still belongs to it; clamp to the tiles that exist.
  // Clamped in double first: u and v may be anything (checked by the caller after).
  const int ut = static_cast<int>(std::clamp(std::floor(u + 0.25), 0.0, static_cast<double>(u_tiles - 1)));
  int vt = static_cast<int>(std::clamp(std::floor(v + 0.25), 0.0, static_cast<double>(corners)));
  if (vt * u_tiles + ut >= corners) vt = corners / u_tiles - 1 + (ut < corners % u_tiles);
  su = 2 * (u - ut);
  sv = 2 * (v - vt);
  return vt * u_tiles + ut;
}

int FaceDomain::subface(const ExactParameter& p, ExactParameter& local) const {
  auto floor_quarter = [](const Fraction& x) {  // floor(x + 1/4)
    const Fraction y = add(x, Fraction{1, 4});
    std::int64_t q = y.num / y.den;
    if (y.num < 0 && q * y.den != y.num) --q;
    return q;
  };
  std::int64_t ut = std::clamp<std::int64_t>(floor_quarter(p.u), 0, u_tiles - 1);
  std::int64_t vt = std::clamp<std::int64_t>(floor_quarter(p.v), 0, corners);
  if (vt * u_tiles + ut >= corners) vt = corners / u_tiles - 1 + (ut < corners % u_tiles);
  local.u = multiply(subtract(p.u, Fraction{ut, 1}), 2);
  local.v = multiply(subtract(p.v, Fraction{vt, 1}), 2);
  return static_cast<int>(vt * u_tiles + ut);
}

}  // namespace stencil_runtime
