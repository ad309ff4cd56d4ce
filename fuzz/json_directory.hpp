#pragma once
// The quad JSON table loader (SurfaceTables::load_json_directory) reads a whole
// directory: v<V>/n<N>.json per valence and rate, regular/n<2N>.json per rate.
// Its fuzz targets mutate files of a valid directory (fuzz/fixtures/nonpoly-json,
// nonpoly at valences 3 and 5, rates 1 and 2) and may add files, names included
// (a rate comes from a file name).
//
// Input format: sections, each a line "@@ <relative path>" followed by the
// file's new content, up to the newline before the next "@@ " line. Paths have
// one to three components of [A-Za-z0-9._+-] (not "." or ".."); a section with
// any other path is ignored. An input that does not start with "@@ " is the
// whole new content of `default_file`.
#include <string>
#include <string_view>

namespace fuzz {

// Rebuilds scratch_dir()/tables from the fixture with the input's files
// written over it, and returns that directory.
std::string json_table_directory(std::string_view input, const std::string& default_file);

}  // namespace fuzz
