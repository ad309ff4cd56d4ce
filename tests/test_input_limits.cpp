// The input limits (base/limits.hpp) and overflow-checked conversions, called
// directly: each limit holds at its value and refuses beyond it, with the
// limit named, and no integer conversion wraps around.
#include <catch2/catch.hpp>
#include <limits>
#include <nlohmann/json.hpp>

#include "algebra/expression.hpp"
#include "algebra/rational.hpp"
#include "base/limits.hpp"
#include "common/json_document.hpp"
#include "common/rate_spec.hpp"

using sg::Rational;
namespace limits = sg::limits;

namespace {
std::string nested(int levels, const std::string& core) {
  return std::string(static_cast<std::size_t>(levels), '(') + core + std::string(static_cast<std::size_t>(levels), ')');
}
// 1 + 1 + ... + 1 with `terms` ones: 2 * terms - 1 characters.
std::string long_sum(long terms) {
  std::string s = "1";
  for (long i = 1; i < terms; ++i) s += "+1";
  return s;
}
}  // namespace

TEST_CASE("formulas: nesting depth, length, exponent and size of intermediate values are bounded", "[limits]") {
  CHECK(sg::evaluate_expression(nested(40, "3/4"), {}) == Rational(3, 4));
  CHECK_THROWS_WITH(sg::evaluate_expression(nested(100, "1"), {}), Catch::Contains("nested more than 64 levels deep"));
  CHECK_THROWS_WITH(sg::evaluate_expression(std::string(100, '-') + "1", {}), Catch::Contains("nested more than 64 levels"));
  std::string tower = "2";
  for (int i = 0; i < 100; ++i) tower += "^2";
  CHECK_THROWS_WITH(sg::evaluate_expression(tower, {}), Catch::Contains("nested more than 64"));
  CHECK_THROWS_WITH(sg::evaluate_expression_real(nested(100, "1"), {}), Catch::Contains("nested more than 64 levels deep"));
  // A sum of many terms is long but flat.
  const long terms = (limits::kMaxExpressionLength + 1) / 2;  // 4095 characters
  CHECK(sg::evaluate_expression(long_sum(terms), {}) == Rational(terms));
  CHECK_THROWS_WITH(sg::evaluate_expression(long_sum(terms) + "+1", {}),
                    Catch::Contains("4097 characters long; the limit is 4096"));
  CHECK(sg::evaluate_expression("2^4096", {}) == Rational(boost::multiprecision::pow(sg::Integer(2), 4096)));
  CHECK(sg::evaluate_expression("2^-4096", {}) == 1 / Rational(boost::multiprecision::pow(sg::Integer(2), 4096)));
  CHECK_THROWS_WITH(sg::evaluate_expression("2^4097", {}), Catch::Contains("above the limit 4096"));
  // 2^4096 has 4097 + 1 bits (numerator and denominator): 8 of its powers fit in 65536 bits, 16 do not.
  CHECK(sg::evaluate_expression("(2^4096)^8", {}) == Rational(boost::multiprecision::pow(sg::Integer(2), 4096 * 8)));
  CHECK_THROWS_WITH(sg::evaluate_expression("(2^4096)^16", {}), Catch::Contains("the limit is 65536"));
  CHECK_THROWS_WITH(sg::evaluate_expression("((2^4096)^4096)^4096", {}), Catch::Contains("the limit is 65536"));
  // Products grow one operand at a time: each step is checked.
  std::string product = "2^4000";
  for (int i = 0; i < 16; ++i) product += "*2^4000";
  CHECK_THROWS_WITH(sg::evaluate_expression(product, {}), Catch::Contains("an intermediate value has"));
  // Long quotes are cut in the message.
  try {
    sg::evaluate_expression(nested(100, "1"), {});
  } catch (const sg::Error& e) {
    CHECK(std::string(e.what()).size() < 300);
  }
}

TEST_CASE("floor, ceiling and long conversions of exact values refuse what does not fit instead of wrapping", "[limits]") {
  const sg::Integer max = std::numeric_limits<long>::max(), min = std::numeric_limits<long>::min();
  CHECK(sg::floor_to_long(Rational(max)) == std::numeric_limits<long>::max());
  CHECK(sg::ceil_to_long(Rational(min)) == std::numeric_limits<long>::min());
  CHECK(sg::floor_to_long(Rational(-7, 2)) == -4);
  CHECK(sg::ceil_to_long(Rational(-7, 2)) == -3);
  CHECK(sg::ceil_to_long(Rational(7, 2)) == 4);
  CHECK_THROWS_WITH(sg::floor_to_long(Rational(max + 1)), Catch::Contains("does not fit in a 64-bit integer"));
  CHECK_THROWS_AS(sg::floor_to_long(Rational(min) - Rational(1, 2)), sg::Error);
  // ceil(x) = -floor(-x) once negated LONG_MIN for x = 2^63 - 1/2; now the negation is exact.
  CHECK_THROWS_AS(sg::ceil_to_long(Rational(max) + Rational(1, 2)), sg::Error);
  CHECK(sg::ceil_to_long(Rational(min) + Rational(1, 2)) == std::numeric_limits<long>::min() + 1);
  CHECK_THROWS_WITH(sg::to_long(max * 4, "the index"), Catch::Contains("the index 36893488147419103228 does not fit"));
  CHECK(sg::floor_integer(Rational(sg::Integer("-100000000000000000000001"), 10)) == sg::Integer("-10000000000000000000001"));
  // cos2pi of a huge argument needs no long at all.
  CHECK(*sg::exact_cos2pi(Rational(sg::Integer("100000000000000000000000000000")) + Rational(1, 4)) == 0);
}

TEST_CASE("rate and valence specs: limits named, numbers of any length read without overflow", "[limits]") {
  CHECK(sg::parse_rate_spec("4096", 4096, "the limit").size() == 4096);
  CHECK_THROWS_WITH(sg::parse_rate_spec("4097", 4096, "the largest rate for curve schemes"),
                    Catch::Contains("4097 is above 4096, the largest rate for curve schemes"));
  CHECK_THROWS_WITH(sg::parse_rate_spec("1-9999999999999", 4096, "the limit"), Catch::Contains("9999999999999 is above 4096"));
  CHECK_THROWS_WITH(sg::parse_rate_spec("99999999999999999999999999999", 4096, "the limit"), Catch::Contains("is above 4096"));
  CHECK_THROWS_WITH(sg::parse_rate_spec("3,", 4096, "the limit"), Catch::Contains("'' is not a positive integer"));
  CHECK(sg::parse_valence_spec("5") == std::vector<int>{5});
  CHECK(sg::parse_valence_spec("62-64,3") == std::vector<int>{3, 62, 63, 64});
  CHECK_THROWS_WITH(sg::parse_valence_spec("65"), Catch::Contains("65 is above 64, the largest valence"));
  CHECK_THROWS_WITH(sg::parse_valence_spec("3-1000"), Catch::Contains("1000 is above 64"));
  CHECK_THROWS_WITH(sg::parse_valence_spec("2-5"), Catch::Contains("valences start at 3"));
  CHECK_NOTHROW(sg::check_valences({3, 10}, 3, 10, "s.json"));
  CHECK_THROWS_WITH(sg::check_valences({3, 11, 12}, 3, 10, "s.json"),
                    Catch::Contains("s.json: valence 11 is outside the range 3..10"));
  CHECK_THROWS_WITH(sg::check_rates({1, 129}, 128, "the largest rate for surface schemes"),
                    Catch::Contains("rate n = 129 is outside 1..128 (the largest rate for surface schemes)"));
}

TEST_CASE("JSON documents: nesting and repeated keys checked while parsing, fields read with their type and range", "[limits]") {
  using nlohmann::json;
  const std::string at_limit = std::string(limits::kMaxJsonDepth, '[') + std::string(limits::kMaxJsonDepth, ']');
  CHECK(sg::parse_json_document<json>(at_limit, "f.json").is_array());
  CHECK_THROWS_WITH(sg::parse_json_document<json>("[" + at_limit + "]", "f.json"),
                    Catch::Contains("f.json: arrays and objects nested deeper than 32 levels"));
  std::string objects;
  for (int i = 0; i < 100000; ++i) objects += "{\"a\":";
  CHECK_THROWS_WITH(sg::parse_json_document<nlohmann::ordered_json>(objects, "f.json"), Catch::Contains("nested deeper than 32"));
  // A key given twice in one object is refused, naming its path; the same key in different objects is fine.
  CHECK_THROWS_WITH(sg::parse_json_document<json>(R"({"a": 1, "a": 1})", "f.json"),
                    Catch::Equals("f.json: a: the key appears twice in its object (which value is meant is ambiguous)"));
  CHECK_THROWS_WITH(sg::parse_json_document<nlohmann::ordered_json>(R"({"a": 1, "b": {"c": [1, [2], {"d": 1, "e": 2, "d": 3}]}})", "f.json"),
                    Catch::StartsWith("f.json: b.c[2].d: the key appears twice"));
  CHECK(sg::parse_json_document<json>(R"({"a": {"x": 1}, "b": [{"x": 1}, {"x": 2}], "x": 3})", "f.json")["x"] == 3);
  CHECK_THROWS_WITH(sg::parse_json_document<json>("{\"a\": 1e999}", "f.json"),
                    Catch::Equals("f.json: not valid JSON: number overflow parsing '1e999'"));
  CHECK_THROWS_WITH(sg::parse_json_document<json>("{\"a\": }", "f.json"),
                    Catch::StartsWith("f.json: not valid JSON: parse error at line 1, column 7"));

  const sg::DocumentReader<json> r("f.json");
  const json doc = json::parse(R"({"big": 18446744073709551615, "neg": -5, "real": 2.0, "text": "2", "q": "1/0"})");
  CHECK_THROWS_WITH(r.integer(doc["big"], "big", 1, 10), Catch::Equals("f.json: big: 18446744073709551615 is outside the range 1..10"));
  CHECK(r.integer(doc["neg"], "neg", -5, 5) == -5);
  CHECK_THROWS_WITH(r.integer(doc["neg"], "neg", -4, 5), Catch::Contains("-5 is outside the range -4..5"));
  CHECK_THROWS_WITH(r.integer(doc["real"], "real", 0, 5), Catch::Contains("expected an integer, got 2.0"));
  CHECK_THROWS_WITH(r.integer(doc["text"], "text", 0, 5), Catch::Contains("expected an integer, got \"2\""));
  CHECK_THROWS_WITH(r.require(doc, "missing", ""), Catch::Equals("f.json: missing required field 'missing'"));
  CHECK_THROWS_WITH(r.rational_literal(doc["q"], sg::field_path(sg::field_path("values", "1/3"), 0)),
                    Catch::StartsWith("f.json: values[\"1/3\"][0]: '1/0' has a zero denominator"));
  CHECK(sg::field_path("functions", 2) == "functions[2]");
  CHECK(sg::field_path("parameters", "w") == "parameters.w");
  CHECK(sg::field_path("values", "12") == "values[\"12\"]");
}
