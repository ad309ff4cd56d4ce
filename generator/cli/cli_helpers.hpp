#pragma once
// Small pieces the commands share.
#include <functional>
#include <iostream>
#include <string>

#include "common/table_encoding.hpp"

namespace sg::cli {

// Progress lines on stderr, unless --quiet.
inline std::function<void(const std::string&)> progress_lines(bool quiet) {
  return [quiet](const std::string& line) {
    if (!quiet) std::cerr << line << "\n";
  };
}

inline BinaryPrecision binary_precision(const std::string& option) {
  return option == "single" ? BinaryPrecision::Single : BinaryPrecision::Double;
}

}  // namespace sg::cli
