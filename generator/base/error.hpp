#pragma once
#include <algorithm>
#include <stdexcept>
#include <string>
#include <string_view>

namespace sg {

// Every user-facing failure of the generator: bad input, unsolvable system, I/O.
// The message is complete (it names the file, value or residue at fault).
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// User text as an error message quotes it: whole when short, else its start,
// so that a 60,000-character formula does not make a 60,000-character message.
// Control characters are shown as \xNN: a NUL would end the message early
// (what() is a C string) and others would garble the terminal.
inline std::string excerpt(std::string_view text) {
  constexpr std::size_t kShown = 60;
  const std::string_view shown = text.substr(0, std::min(text.size(), kShown));
  std::string out;
  for (const char c : shown) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte != 0x7f) {
      out += c;
      continue;
    }
    static constexpr char kHex[] = "0123456789abcdef";
    out += "\\x";
    out += kHex[byte >> 4];
    out += kHex[byte & 15];
  }
  return text.size() <= kShown ? out : out + "...";
}

}  // namespace sg
