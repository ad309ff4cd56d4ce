#pragma once
// Reading PLY files (ASCII, binary little- or big-endian): the vertices' x, y,
// z and, where asked, the faces of the `face` element. One reader for the
// tools' points files (stencildist, stencilfit) and for control meshes
// (read_ply_mesh), so both refuse the same faults with the same messages.
#include <string>
#include <vector>

#include "stencil_runtime/mesh.hpp"

namespace stencil_runtime::detail {

struct PlyContent {
  std::vector<Point> points;
  // With `faces`: the lists `vertex_indices` (or `vertex_index`) of the
  // element `face`, each list's size and then its indices as written (not
  // yet checked against the vertices).
  bool has_faces = false;  // the file has a face element with such a list
  std::vector<long long> face_sizes, face_vertices;
};

// `data`: the whole file. The first element must be `vertex` with float or
// double x, y, z (its other properties, scalars of any type, are skipped);
// later elements are walked, so that a file cut short, or longer than its
// header says, is refused. Throws LoadError naming `path` and the header
// line, the text line or the binary item.
PlyContent read_ply(const std::string& path, const std::string& data, bool faces);

}  // namespace stencil_runtime::detail
