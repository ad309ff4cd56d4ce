#pragma once
// Splitting a line of a text mesh file (OBJ) into whitespace-separated tokens.
#include <cctype>
#include <charconv>
#include <cstddef>
#include <string_view>
#include <vector>

namespace stencil_runtime::detail {

// The next token of `line` from `pos` (spaces, tabs and a trailing '\r'
// separate them), advancing `pos`; empty at the end of the line.
inline std::string_view next_token(std::string_view line, std::size_t& pos) {
  while (pos < line.size() && (line[pos] == ' ' || line[pos] == '\t' || line[pos] == '\r')) ++pos;
  const std::size_t begin = pos;
  while (pos < line.size() && line[pos] != ' ' && line[pos] != '\t' && line[pos] != '\r') ++pos;
  return line.substr(begin, pos - begin);
}

// The whitespace-separated words of `line` (spaces, tabs, '\r' and the other
// white space of the C locale).
inline std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    std::size_t j = i;
    while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
    if (j > i) words.push_back(line.substr(i, j - i));
    i = j;
  }
  return words;
}

// Whether the whole of `word` is an integer (a number), stored in `out`.
inline bool whole_number(std::string_view word, long long& out) {
  const auto [stop, err] = std::from_chars(word.data(), word.data() + word.size(), out);
  return err == std::errc() && stop == word.data() + word.size();
}
inline bool real_number(std::string_view word, double& out) {
  const auto [stop, err] = std::from_chars(word.data(), word.data() + word.size(), out);
  return err == std::errc() && stop == word.data() + word.size();
}

}  // namespace stencil_runtime::detail
