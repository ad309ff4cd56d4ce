#include "common/table_encoding.hpp"

#include <numeric>

#include "common/byte_writer.hpp"

namespace sg {
using ojson = nlohmann::ordered_json;

ojson exact_entry_json(const ScaledVector& w, const Rational& x, const Rational& y) {
  ojson e;
  e["at"] = {to_string(x), to_string(y)};
  e["denominator"] = w.den.str();
  ojson nums = ojson::array();
  for (const auto& v : w.num) nums.push_back(v.str());
  e["numerators"] = nums;
  return e;
}

void put_scalar(std::string& out, double d, BinaryPrecision p) {
  if (p == BinaryPrecision::Double)
    put<double>(out, d);
  else
    put<float>(out, static_cast<float>(d));
}

std::pair<long, long> reduced_fraction(long p, long q) {
  const long g = std::gcd(p, q);
  return {p / g, q / g};
}

}  // namespace sg
