#pragma once
#include <stdexcept>
#include <string>

namespace sg {

// Every user-facing failure of the generator: bad input, unsolvable system, I/O.
// The message is complete (it names the file, value or residue at fault).
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace sg
