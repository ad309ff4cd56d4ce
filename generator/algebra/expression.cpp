#include "algebra/expression.hpp"

#include <boost/math/constants/constants.hpp>
#include <cctype>
#include <type_traits>

#include "base/error.hpp"
#include "base/limits.hpp"

namespace sg {
namespace {

bool is_integer(const Rational& x) { return denominator(x) == 1; }
bool is_integer(const Real& x) { return floor(x) == x; }
long to_long(const Rational& x) { return numerator(x).convert_to<long>(); }
long to_long(const Real& x) { return x.convert_to<long>(); }

long bits(const Integer& x) { return x == 0 ? 0 : static_cast<long>(msb(abs(x))) + 1; }
// The size of an exact value (numerator and denominator); Reals have a fixed size.
long bits(const Rational& x) { return bits(numerator(x)) + bits(denominator(x)); }
long bits(const Real&) { return 0; }

// Recursive descent over:  expr := term (('+'|'-') term)*
//                          term := unary (('*'|'/') unary)*
//                          unary := ('+'|'-') unary | power
//                          power := atom ('^' unary)?
//                          atom := integer | name | '(' expr ')'
// T is Rational (exact; an irrational cos2pi is refused with IrrationalValue)
// or Real (cos2pi in high precision). Every recursion passes through unary(),
// which counts the nesting depth; exact intermediate results are bounded in
// size (limits.hpp).
template <class T>
class Parser {
 public:
  Parser(std::string_view text, const Bindings& bindings) : text_(text), bindings_(bindings) {}

  T parse() {
    if (static_cast<long>(text_.size()) > limits::kMaxExpressionLength)
      fail("the formula is " + std::to_string(text_.size()) + " characters long; the limit is " +
           std::to_string(limits::kMaxExpressionLength));
    T value = expr();
    skip_space();
    if (pos_ != text_.size()) fail("unexpected '" + std::string(1, text_[pos_]) + "'");
    return value;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw Error("in expression \"" + excerpt(text_) + "\" at position " + std::to_string(pos_ + 1) + ": " + what);
  }
  // `value`, unless an exact value has outgrown the size limit.
  T sized(T value) const {
    if (bits(value) > limits::kMaxExpressionBits)
      fail("an intermediate value has " + std::to_string(bits(value)) + " bits (numerator and denominator); the limit is " +
           std::to_string(limits::kMaxExpressionBits));
    return value;
  }
  // Counts one nesting level for as long as it lives.
  class Level {
   public:
    explicit Level(Parser& p) : p_(p) {
      if (++p_.depth_ > limits::kMaxExpressionDepth)
        p_.fail("nested more than " + std::to_string(limits::kMaxExpressionDepth) +
                " levels deep (parentheses, signs and powers); that is the limit");
    }
    ~Level() { --p_.depth_; }
    Level(const Level&) = delete;
    Level& operator=(const Level&) = delete;

   private:
    Parser& p_;
  };
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool accept(char c) {
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  T expr() {
    T value = term();
    for (;;) {
      if (accept('+')) value = sized(value + term());
      else if (accept('-')) value = sized(value - term());
      else return value;
    }
  }
  T term() {
    T value = unary();
    for (;;) {
      if (accept('*')) {
        value = sized(value * unary());
      } else if (accept('/')) {
        const std::size_t at = pos_;
        T divisor = unary();
        if (divisor == 0) {
          pos_ = at;
          fail("division by zero");
        }
        value = sized(value / divisor);
      } else {
        return value;
      }
    }
  }
  T unary() {
    const Level level(*this);
    if (accept('-')) return -unary();
    if (accept('+')) return unary();
    return power();
  }
  T power() {
    T base = atom();
    if (!accept('^')) return base;
    const std::size_t at = pos_;
    const T exponent = unary();
    if (!is_integer(exponent)) {
      pos_ = at;
      fail("exponent must be an integer");
    }
    if (abs(exponent) > limits::kMaxExponent) {
      pos_ = at;
      fail("the exponent's magnitude is above the limit " + std::to_string(limits::kMaxExponent));
    }
    const long e = to_long(exponent), magnitude = e < 0 ? -e : e;
    if (e < 0 && base == 0) fail("zero to a negative power");
    if (magnitude * bits(base) > limits::kMaxExpressionBits) {  // checked before the work, not after
      pos_ = at;
      fail("the power would have about " + std::to_string(magnitude * bits(base)) +
           " bits (numerator and denominator); the limit is " + std::to_string(limits::kMaxExpressionBits));
    }
    T result = 1;
    for (long i = 0; i < magnitude; ++i) result *= base;
    return e < 0 ? T(1 / result) : result;
  }
  T atom() {
    skip_space();
    if (pos_ >= text_.size()) fail("unexpected end");
    const char c = text_[pos_];
    if (c == '(') {
      ++pos_;
      T value = expr();
      if (!accept(')')) fail("missing ')'");
      return value;
    }
    if (std::isdigit(static_cast<unsigned char>(c))) {
      const std::size_t start = pos_;
      while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
      return sized(T(Integer(std::string(text_.substr(start, pos_ - start)))));
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      const std::size_t start = pos_;
      while (pos_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_')) ++pos_;
      const std::string name(text_.substr(start, pos_ - start));
      if (name == "cos2pi" && accept('(')) {
        const T arg = expr();
        if (!accept(')')) fail("missing ')' after cos2pi(...");
        if constexpr (std::is_same_v<T, Rational>) {
          const auto value = exact_cos2pi(arg);
          if (!value)
            throw IrrationalValue("in expression \"" + std::string(text_) + "\" at position " + std::to_string(start + 1) +
                                  ": cos2pi(" + to_string(arg) + ") = cos(2 pi * " + to_string(arg) +
                                  ") is irrational, and this exact evaluator only takes rational values");
          return *value;
        } else {
          return cos(2 * boost::math::constants::pi<T>() * arg);
        }
      }
      const auto it = bindings_.find(name);
      if (it == bindings_.end()) {
        pos_ = start;
        fail("unknown name '" + name + "'");
      }
      return T(it->second);
    }
    fail("unexpected '" + std::string(1, c) + "'");
  }

  std::string_view text_;
  const Bindings& bindings_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

}  // namespace

std::optional<Rational> exact_cos2pi(const Rational& r) {
  // Niven: cos(2 pi r) is rational only where it is 0, +-1/2 or +-1.
  const Rational frac = r - Rational(floor_integer(r));
  const Rational table[][2] = {{Rational(0), Rational(1)},       {Rational(1, 6), Rational(1, 2)},
                               {Rational(1, 4), Rational(0)},    {Rational(1, 3), Rational(-1, 2)},
                               {Rational(1, 2), Rational(-1)},   {Rational(2, 3), Rational(-1, 2)},
                               {Rational(3, 4), Rational(0)},    {Rational(5, 6), Rational(1, 2)}};
  for (const auto& row : table)
    if (frac == row[0]) return row[1];
  return std::nullopt;
}

Rational evaluate_expression(std::string_view text, const Bindings& bindings) {
  return Parser<Rational>(text, bindings).parse();
}

Real evaluate_expression_real(std::string_view text, const Bindings& bindings) {
  return Parser<Real>(text, bindings).parse();
}

}  // namespace sg
