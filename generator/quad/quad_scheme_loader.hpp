#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "common/scheme_registry.hpp"
#include "quad/quad_scheme.hpp"

namespace sg {

// Loads a scheme file of type "quad" (docs/scheme-format.md). The regular curve
// scheme it names is loaded from the same directory. Checks that the valence-4
// rules are exactly the tensor product of the curve scheme. Errors name the
// file and field.
QuadScheme load_quad_scheme(const std::string& spec, const std::vector<std::string>& overrides = {},
                            const std::filesystem::path& dir = default_schemes_dir());

// The same from a scheme document in memory; `origin` names it in errors (and
// becomes `source`); the regular curve scheme is looked up in `curve_dir`.
QuadScheme quad_scheme_from_json(const std::string& text, const std::string& origin,
                                 const std::vector<std::string>& overrides,
                                 const std::filesystem::path& curve_dir = default_schemes_dir());

}  // namespace sg
