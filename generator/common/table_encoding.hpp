#pragma once
// What the table writers of the families share: the exact stencil entry of the
// JSON tables, the scalar precision of the binary tables, and reduced
// parameter points.
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "algebra/rational.hpp"
#include "algebra/scaled_vector.hpp"

namespace sg {

// One exact stencil entry of a table file: {"at": [x, y], "denominator", "numerators"}
// (the quad and the exact triangle tables share it).
nlohmann::ordered_json exact_entry_json(const ScaledVector& w, const Rational& x, const Rational& y);

enum class BinaryPrecision { Double = 8, Single = 4 };

// One stored scalar, float64 or float32 (the binary tables' weights).
void put_scalar(std::string& out, double value, BinaryPrecision precision);

// p/q in lowest terms, so that equal parameter points of different grids share one stored stencil.
std::pair<long, long> reduced_fraction(long p, long q);

}  // namespace sg
