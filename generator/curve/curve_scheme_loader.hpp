#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "curve/curve_scheme.hpp"

namespace sg {

// Directory searched for `--scheme NAME`: $STENCILGEN_SCHEMES_DIR, else the
// source tree's schemes/ folder.
std::filesystem::path default_schemes_dir();

// `spec` is a file path (contains '/' or ends in .json) or a scheme name looked
// up in `dir`. `overrides` are NAME=RATIONAL strings for declared parameters.
CurveScheme load_curve_scheme(const std::string& spec, const std::vector<std::string>& overrides = {},
                              const std::filesystem::path& dir = default_schemes_dir());

enum class SchemeFamily { Any, Curve, Quad, Triangle };

// Names of the *.json files in `dir` (sorted), for listings and error messages;
// with a family, only the files whose "type" belongs to it.
std::vector<std::string> available_schemes(const std::filesystem::path& dir = default_schemes_dir(),
                                           SchemeFamily family = SchemeFamily::Any);

}  // namespace sg
