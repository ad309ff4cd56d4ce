#pragma once
// Sparse rows of exact weights as the JSON tables store them (a row is a list
// of [column, "p/q"] pairs): written, read back with every column and weight
// checked, and the check that a limit stencil is its A0's fixed point, done
// with the file's own rationals. Shared by the quad descent and the Loop
// sectors.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "algebra/rational.hpp"
#include "common/json_document.hpp"

namespace sg {

using ExactRow = std::vector<std::pair<std::size_t, Rational>>;  // (column, weight)

// Longest weight a file may hold, in characters: the generator's are far
// shorter, and a longer one would only cost time to parse.
inline constexpr std::size_t kMaxWeightLiteral = 4096;

// A stored weight as an exact rational, at most kMaxWeightLiteral characters.
Rational exact_weight(const DocumentReader<nlohmann::ordered_json>& r, const nlohmann::ordered_json& j, const std::string& field);

// `rows` (at `field`): an array of rows of [column, weight] pairs, every column below `columns`.
std::vector<ExactRow> exact_rows(const DocumentReader<nlohmann::ordered_json>& r, const nlohmann::ordered_json& rows,
                                 const std::string& field, std::size_t columns);

// Rows as written; `text` turns a weight into its literal.
template <class Rows, class Text>
nlohmann::ordered_json exact_rows_json(const Rows& rows, Text text) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const auto& row : rows) {
    nlohmann::ordered_json r = nlohmann::ordered_json::array();
    for (const auto& [column, weight] : row) r.push_back({column, text(weight)});
    out.push_back(r);
  }
  return out;
}

// What keeps `limit` from being the limit stencil of the rows A0 (a row per
// point): a sum other than 1, W A0 != W, or a wrong length; none if it is one.
std::vector<std::string> limit_stencil_faults(const std::vector<Rational>& limit, const std::vector<ExactRow>& a0);

}  // namespace sg
