#pragma once
#include <optional>
#include <string>

#include "common/table_document.hpp"
#include "triangle/triangle_scheme.hpp"
#include "triangle/triangle_table.hpp"

namespace sg {

// A triangle table (JSON) re-solved from its scheme: `fresh` is the table
// solved anew at the valence and rate the file records, `same` whether the
// file equals its serialisation in every byte. Throws sg::Error naming the
// file and field when the table is malformed, or when its valence or rate is
// outside the limits (checked before solving).
struct TriangleTableCheck {
  TriangleTable fresh;
  bool same = false;
  std::optional<std::string> difference;  // where the file first differs from the re-solved table
};
TriangleTableCheck verify_triangle_table(const TableDocument& table, const TriangleScheme& scheme);

}  // namespace sg
