#pragma once
// Splitting a line of a text mesh file (OBJ) into whitespace-separated tokens.
#include <cstddef>
#include <string_view>

namespace stencil_runtime::detail {

// The next token of `line` from `pos` (spaces, tabs and a trailing '\r'
// separate them), advancing `pos`; empty at the end of the line.
inline std::string_view next_token(std::string_view line, std::size_t& pos) {
  while (pos < line.size() && (line[pos] == ' ' || line[pos] == '\t' || line[pos] == '\r')) ++pos;
  const std::size_t begin = pos;
  while (pos < line.size() && line[pos] != ' ' && line[pos] != '\t' && line[pos] != '\r') ++pos;
  return line.substr(begin, pos - begin);
}

}  // namespace stencil_runtime::detail
