#pragma once
// The runtime's one error base type: every failure the library reports is a
// stencil_runtime::Error (or one of the kinds below), with a complete message
// that names the file, face, vertex or value at fault.
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
