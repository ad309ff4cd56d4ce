#pragma once
// What the text mesh readers (OBJ, OFF) share: opening a mesh file within the
// stated limits, and reading it a line at a time without ever holding a line
// longer than limits::kMaxMeshLineBytes.
#include <fstream>
#include <streambuf>
#include <string>

#include "stencil_runtime/limits.hpp"

namespace stencil_runtime::detail {

// The file opened for reading, or LoadError naming it: no such file, not a
// regular file, larger than limits::kMaxMeshFileBytes.
std::ifstream open_mesh_file(const std::string& path);

// One line (without its '\n'); false at the end of the input. Calls `fail`
// (which throws) for a line longer than the limit, before reading it whole.
template <class Fail>
bool next_line(std::streambuf& in, std::string& line, const Fail& fail) {
  line.clear();
  int c = in.sbumpc();
  if (c == std::char_traits<char>::eof()) return false;
  while (c != std::char_traits<char>::eof() && c != '\n') {
    if (line.size() >= limits::kMaxMeshLineBytes)
      fail("line longer than " + std::to_string(limits::kMaxMeshLineBytes) + " bytes");
    line.push_back(static_cast<char>(c));
    c = in.sbumpc();
  }
  return true;
}

}  // namespace stencil_runtime::detail
