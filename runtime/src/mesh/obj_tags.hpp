#pragma once
// OpenSubdiv's OBJ tag lines (`t name I/F/S ints floats strings`, the
// convention of its regression shapes; `I/F` without the string count is
// accepted too): crease, corner, hole, interpolateboundary, creasemethod and
// smoothtriangles, read into Mesh::tags with their line numbers. Unknown tag
// names become a warning in Mesh::warnings; a malformed line is an error.
#include <functional>
#include <string>
#include <string_view>

#include "stencil_runtime/mesh.hpp"

namespace stencil_runtime::detail {

using TagFail = std::function<void(const std::string&)>;  // throws, naming the file and line

// `rest`: the line after its `t`. `where`: "file:line", for warnings.
void read_obj_tag(std::string_view rest, long line, const std::string& where, Mesh& mesh, const TagFail& fail);

// After the whole file: every tagged vertex, edge and face exists. `fail_at`
// throws naming the file and the given line.
void check_obj_tags(const Mesh& mesh, const std::function<void(long, const std::string&)>& fail_at);

}  // namespace stencil_runtime::detail
