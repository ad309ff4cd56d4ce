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

}  // namespace sg
