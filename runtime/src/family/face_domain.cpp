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

void FaceDomain::clamp(double& u, double& v) const {
  switch (kind) {
    case Kind::Quad:
      u = std::clamp(u, 0.0, 1.0), v = std::clamp(v, 0.0, 1.0);
      return;
    case Kind::Triangle:
      u = std::max(u, 0.0), v = std::max(v, 0.0);
      if (u + v > 1) {  // the nearest point of the hypotenuse
        u = std::clamp(u - (u + v - 1) / 2, 0.0, 1.0);
        v = 1 - u;  // u + v rounds to 1 at most
      }
      return;
    default: {
      double su = 0, sv = 0;
      const int s = subface(u, v, su, sv);
      su = std::clamp(su, 0.0, 1.0), sv = std::clamp(sv, 0.0, 1.0);
      u = s % u_tiles + su / 2, v = s / u_tiles + sv / 2;
    }
  }
}

namespace {

// Whether a parameter lies in the domain is decided in 128 bits: products of
// two 64-bit values fit, so no parameter the type holds throws here (the
// evaluation after it may still need to leave exact arithmetic).
__extension__ typedef __int128 Wide;  // GCC and Clang: no warning under -Wpedantic

// floor(x + 1/4) = floor((4 num + den) / (4 den)).
std::int64_t floor_quarter(const Fraction& x) {
  const Wide n = 4 * static_cast<Wide>(x.num) + x.den, d = 4 * static_cast<Wide>(x.den);
  Wide q = n / d;
  if (n < 0 && q * d != n) --q;
  return static_cast<std::int64_t>(std::clamp<Wide>(q, INT64_MIN, INT64_MAX));
}

// Whether t <= x <= t + 1/2 (the tile [t, t + 1/2] along one axis).
bool in_tile(const Fraction& x, std::int64_t t) {
  const Wide n = x.num, d = x.den;
  return n >= t * d && 2 * n <= (2 * static_cast<Wide>(t) + 1) * d;
}

}  // namespace

bool FaceDomain::contains(const ExactParameter& p) const {
  const Fraction zero{0, 1}, one{1, 1};
  if (compare(p.u, zero) < 0 || compare(p.v, zero) < 0) return false;
  switch (kind) {
    case Kind::Quad: return compare(p.u, one) <= 0 && compare(p.v, one) <= 0;
    case Kind::Triangle:  // u + v <= 1
      return static_cast<Wide>(p.u.num) * p.v.den + static_cast<Wide>(p.v.num) * p.u.den <=
             static_cast<Wide>(p.u.den) * p.v.den;
    default: {
      std::int64_t ut = 0, vt = 0;
      tiles(floor_quarter(p.u), floor_quarter(p.v), ut, vt);
      return in_tile(p.u, ut) && in_tile(p.v, vt);
    }
  }
}

void FaceDomain::tiles(std::int64_t u_floor, std::int64_t v_floor, std::int64_t& ut, std::int64_t& vt) const {
  // Bfr's rule: a point within 1/4 beyond a tile still belongs to it; clamp to the tiles that exist.
  ut = std::clamp<std::int64_t>(u_floor, 0, u_tiles - 1);
  vt = std::clamp<std::int64_t>(v_floor, 0, corners);
  if (vt * u_tiles + ut >= corners) vt = corners / u_tiles - 1 + (ut < corners % u_tiles);
}

int FaceDomain::subface(double u, double v, double& su, double& sv) const {
  // Clamped in double first: u and v may be anything (checked by the caller
  // after); NaN, which no clamp changes, counts as 0 rather than reaching an
  // undefined conversion to int.
  auto floor_quarter = [](double x) { return x == x ? std::clamp(std::floor(x + 0.25), -1.0, 1e9) : 0.0; };
  std::int64_t ut = 0, vt = 0;
  tiles(static_cast<std::int64_t>(floor_quarter(u)), static_cast<std::int64_t>(floor_quarter(v)), ut, vt);
  su = 2 * (u - static_cast<double>(ut));
  sv = 2 * (v - static_cast<double>(vt));
  return static_cast<int>(vt * u_tiles + ut);
}

int FaceDomain::subface(const ExactParameter& p, ExactParameter& local) const {
  std::int64_t ut = 0, vt = 0;
  tiles(floor_quarter(p.u), floor_quarter(p.v), ut, vt);
  local.u = multiply(subtract(p.u, Fraction{ut, 1}), 2);
  local.v = multiply(subtract(p.v, Fraction{vt, 1}), 2);
  return static_cast<int>(vt * u_tiles + ut);
}

}  // namespace stencil_runtime
