#include "common/exact_rows.hpp"

namespace sg {

using ojson = nlohmann::ordered_json;

Rational exact_weight(const DocumentReader<ojson>& r, const ojson& j, const std::string& field) {
  if (j.is_string() && j.get_ref<const std::string&>().size() > kMaxWeightLiteral)
    r.fail(field, "is longer than " + std::to_string(kMaxWeightLiteral) + " characters");
  return r.rational_literal(j, field);
}

std::vector<ExactRow> exact_rows(const DocumentReader<ojson>& r, const ojson& rows, const std::string& field, std::size_t columns) {
  std::vector<ExactRow> out;
  const ojson& list = r.array(rows, field);
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::string f = field_path(field, k);
    ExactRow row;
    const ojson& pairs = r.array(list[k], f);
    for (std::size_t e = 0; e < pairs.size(); ++e) {
      const std::string fe = field_path(f, e);
      const ojson& pair = r.array(pairs[e], fe);
      if (pair.size() != 2) r.fail(fe, "expected [column, weight]");
      const long column = r.integer(pair[0], field_path(fe, 0), 0, static_cast<long>(columns) - 1);
      row.emplace_back(static_cast<std::size_t>(column), exact_weight(r, pair[1], field_path(fe, 1)));
    }
    out.push_back(std::move(row));
  }
  return out;
}

std::vector<std::string> limit_stencil_faults(const std::vector<Rational>& limit, const std::vector<ExactRow>& a0) {
  if (a0.size() != limit.size())
    return {"A0 has " + std::to_string(a0.size()) + " rows for " + std::to_string(limit.size()) + " limit weights"};
  std::vector<Rational> image(limit.size(), Rational(0));
  Rational sum(0);
  for (std::size_t row = 0; row < limit.size(); ++row) {
    sum += limit[row];
    for (const auto& [column, weight] : a0[row]) {
      if (column >= image.size()) return {"A0 has a column " + std::to_string(column) + " beyond its " + std::to_string(image.size()) + " points"};
      image[column] += limit[row] * weight;
    }
  }
  std::vector<std::string> faults;
  if (sum != Rational(1)) faults.push_back("the limit stencil sums to " + to_string(sum) + ", not 1");
  if (image != limit) faults.push_back("the limit stencil is not A0's fixed point (W(0) A0 != W(0))");
  return faults;
}

}  // namespace sg
