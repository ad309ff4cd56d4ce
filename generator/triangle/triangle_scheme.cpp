#include "triangle/triangle_scheme.hpp"

#include "base/error.hpp"

namespace sg {
namespace {

void check_range(const TriangleScheme& s, int valence) {
  if (valence < s.min_valence || valence > s.max_valence)
    throw Error(s.source + ": valence " + std::to_string(valence) + " is outside the range " +
                std::to_string(s.min_valence) + ".." + std::to_string(s.max_valence) + " the scheme covers");
}

std::string context(const TriangleScheme& s, int valence) {
  return s.source + ": rules.vertex.neighbour at v = " + std::to_string(valence) + ": ";
}

}  // namespace

std::optional<Rational> TriangleScheme::exact_neighbour_weight(int valence) const {
  check_range(*this, valence);
  Bindings b = parameters;
  b["v"] = valence;
  try {
    return evaluate_expression(vertex_neighbour, b);
  } catch (const IrrationalValue&) {
    return std::nullopt;
  } catch (const Error& e) {
    throw Error(context(*this, valence) + e.what());
  }
}

Real TriangleScheme::real_neighbour_weight(int valence) const {
  check_range(*this, valence);
  Bindings b = parameters;
  b["v"] = valence;
  try {
    return evaluate_expression_real(vertex_neighbour, b);
  } catch (const Error& e) {
    throw Error(context(*this, valence) + e.what());
  }
}

}  // namespace sg
