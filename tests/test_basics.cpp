#include <catch2/catch.hpp>
#include <cmath>

#include "algebra/expression.hpp"
#include "algebra/rational.hpp"
#include "base/error.hpp"
#include "common/rate_spec.hpp"

using sg::Rational;

TEST_CASE("exact expressions evaluate with parameters and reject bad input") {
  const sg::Bindings w{{"w", Rational(1, 16)}, {"v", Rational(5)}};
  CHECK(sg::evaluate_expression("1/2 + w", w) == Rational(9, 16));
  CHECK(sg::evaluate_expression("-w", w) == Rational(-1, 16));
  CHECK(sg::evaluate_expression("3/(2*v) - 2^-1", w) == Rational(3, 10) - Rational(1, 2));
  CHECK(sg::evaluate_expression("(1 - w)^2", w) == Rational(225, 256));
  CHECK_THROWS_WITH(sg::evaluate_expression("1/(w-w)", w), Catch::Contains("division by zero"));
  CHECK_THROWS_WITH(sg::evaluate_expression("1/2 + x", w), Catch::Contains("unknown name 'x'"));
  CHECK_THROWS_WITH(sg::evaluate_expression("0.0625", w), Catch::Contains("unexpected '.'"));
  CHECK_THROWS_WITH(sg::evaluate_expression("(1", w), Catch::Contains("missing ')'"));
}

TEST_CASE("rationals parse, print and round to the nearest double") {
  CHECK(sg::parse_rational("-8/3") == Rational(-8, 3));
  CHECK(sg::to_string(Rational(-16, 6)) == "-8/3");
  CHECK(sg::to_string(Rational(4, 2)) == "2");
  CHECK_THROWS_AS(sg::parse_rational("1/0"), sg::Error);
  CHECK_THROWS_AS(sg::parse_rational("1.5"), sg::Error);
  CHECK(sg::to_double(Rational(1, 3)) == 1.0 / 3.0);
  CHECK(sg::to_double(Rational(-2000, 5589)) == -2000.0 / 5589.0);
  // 2^53 + 1 lies halfway between two doubles: ties go to even (2^53).
  const Rational tie = Rational(sg::Integer(1) << 53) + 1;
  CHECK(sg::to_double(tie) == std::ldexp(1.0, 53));
  CHECK(sg::to_double(tie + Rational(1, 1000)) == std::ldexp(1.0, 53) + 2.0);
}

TEST_CASE("rate specs") {
  CHECK(sg::parse_rate_spec("4", 4096, "the limit") == std::vector<long>{1, 2, 3, 4});
  CHECK(sg::parse_rate_spec("12-14", 4096, "the limit") == std::vector<long>{12, 13, 14});
  CHECK(sg::parse_rate_spec("7,3,5,3", 4096, "the limit") == std::vector<long>{3, 5, 7});
  CHECK(sg::parse_rate_spec("1-2,9", 4096, "the limit") == std::vector<long>{1, 2, 9});
  CHECK_THROWS_WITH(sg::parse_rate_spec("0", 4096, "the limit"), Catch::Contains("less than 1"));
  CHECK_THROWS_WITH(sg::parse_rate_spec("-3", 4096, "the limit"), Catch::Contains("not a positive integer"));
  CHECK_THROWS_WITH(sg::parse_rate_spec("5-2", 4096, "the limit"), Catch::Contains("empty"));
  CHECK_THROWS_WITH(sg::parse_rate_spec("abc", 4096, "the limit"), Catch::Contains("not a positive integer"));
}
