#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "common/scheme_registry.hpp"
#include "triangle/triangle_scheme.hpp"

namespace sg {

// Loads a scheme file of type "triangle" (docs/scheme-format.md). Checks that
// the weights are affine, that valence 6 gives rational regular weights (the
// regular scaling function is solved exactly), and that every valence in range
// evaluates. A "crease_curve" names a curve scheme in the same directory
// whose mask gives the crease rule (binary, symmetric, on [-2, 2], midpoint
// edge rule). Errors name the file and field.
TriangleScheme load_triangle_scheme(const std::string& spec, const std::vector<std::string>& overrides = {},
                                    const std::filesystem::path& dir = default_schemes_dir());

// The same from a scheme document in memory; `origin` names it in errors (and
// becomes `source`); a crease curve is looked up in `curve_dir`.
TriangleScheme triangle_scheme_from_json(const std::string& text, const std::string& origin,
                                         const std::vector<std::string>& overrides = {},
                                         const std::filesystem::path& curve_dir = default_schemes_dir());

}  // namespace sg
