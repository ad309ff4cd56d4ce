#pragma once
// The runtime's one error base type: every failure the library reports is a
// stencil_runtime::Error (or one of the kinds below), with a complete message
// that names the file, face, vertex or value at fault.
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

namespace stencil_runtime {

struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A table or mesh file that cannot be read, or whose contents break its format or the limits.
struct LoadError : Error {
  using Error::Error;
};

// A mesh the runtime cannot evaluate: its topology, a valence or a face size.
struct MeshError : Error {
  using Error::Error;
};

// A request outside what a surface and its tables hold: a face, parameter, rate or position.
struct EvaluationError : Error {
  using Error::Error;
};

// A number as a message writes it: as few digits as give back the same double
// (1e37, 0.1, -1, 1e-30; not to_string's 10000000000000000000000000000000000000.000000
// or 0.000000), all 17 where fewer do not; an exponent without '+' or leading zeros.
inline std::string number_text(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.15g", x);
  if (std::strtod(text, nullptr) != x) std::snprintf(text, sizeof text, "%.17g", x);
  std::string out = text;
  const std::size_t e = out.find('e');
  if (e != std::string::npos) {
    std::size_t digits = e + 1;
    if (out[digits] == '+') out.erase(digits, 1);
    else if (out[digits] == '-') ++digits;
    while (digits + 1 < out.size() && out[digits] == '0') out.erase(digits, 1);
  }
  return out;
}

// User text as a message quotes it: 'text' when short, else its start and its
// length, so that a 100,000-character argument does not make a message as long.
// Control characters are shown as \xNN: a NUL would end the message there
// (what() is a C string), a newline would break its one line, and others
// would garble the terminal.
inline std::string quoted_excerpt(std::string_view text) {
  constexpr std::size_t kShown = 60;
  std::string out(1, '\'');
  for (const char c : text.substr(0, kShown)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte != 0x7f) {
      out.push_back(c);
    } else {
      const char* const hex = "0123456789abcdef";
      out.append("\\x").append(1, hex[byte >> 4]).append(1, hex[byte & 15]);
    }
  }
  if (text.size() <= kShown) return out.append(1, '\'');
  return out.append("...' (").append(std::to_string(text.size())).append(" characters)");
}

}  // namespace stencil_runtime
