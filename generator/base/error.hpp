#pragma once
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
inline std::string excerpt(std::string_view text) {
  constexpr std::size_t kShown = 60;
  return text.size() <= kShown ? std::string(text) : std::string(text.substr(0, kShown)) + "...";
}

}  // namespace sg
