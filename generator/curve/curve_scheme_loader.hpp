#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "common/scheme_registry.hpp"
#include "curve/curve_scheme.hpp"

namespace sg {

// `spec` is a file path (contains '/' or ends in .json) or a scheme name looked
// up in `dir`. `overrides` are NAME=RATIONAL strings for declared parameters.
CurveScheme load_curve_scheme(const std::string& spec, const std::vector<std::string>& overrides = {},
                              const std::filesystem::path& dir = default_schemes_dir());

// The same from a scheme document in memory; `origin` names it in errors (and becomes `source`).
CurveScheme curve_scheme_from_json(const std::string& text, const std::string& origin,
                                   const std::vector<std::string>& overrides = {});

}  // namespace sg
