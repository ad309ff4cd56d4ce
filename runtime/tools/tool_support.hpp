#pragma once
// What the runtime's command-line tools share: the error boundary of every
// main, checked reading of small text inputs, parameter parsing, and the
// printf-style output-name patterns of animations.
#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

#include "stencil_runtime/exact_parameter.hpp"
#include "stencil_runtime/mesh.hpp"

namespace stencil_tools {

// Parses the command line and runs `body`, turning every exception into one
// line "<tool>: error: <message>" on stderr and exit code 1. --help prints
// the help and exits 0; a command-line error is one line and exit code 1.
int run_tool(CLI::App& app, int argc, char** argv, const std::function<int()>& body);

// Whether two meshes' tags give the same surface rules: the same creases (an
// edge in either direction) and corners with the same sharpness, the same
// holes and options, in any order and from any lines.
bool same_tags(const stencil_runtime::MeshTags& a, const stencil_runtime::MeshTags& b);
// Whether a mesh has no tags: no creases, corners or holes and the default options.
bool untagged(const stencil_runtime::MeshTags& tags);

// A regular text file of at most `max_bytes`, whole; errors name the path.
std::string read_text_file(const std::string& path, std::size_t max_bytes = std::size_t{64} << 20);

// Writes `text` to a temporary file beside `path` and renames it into place,
// so that a failure leaves nothing behind; errors name the path.
void write_text_file(const std::string& path, const std::string& text);

// A parameter as given on the command line: an exact rational ("1/3", "0",
// "1") or a decimal ("0.3", "2.5e-3"), which is evaluated within a tolerance.
struct ParameterText {
  bool exact = true;
  stencil_runtime::Fraction fraction;
  double value = 0;
};
ParameterText parse_parameter(const std::string& text);

// Splits "U,V" (exactly one comma); `option` names the option in errors.
std::pair<std::string, std::string> split_pair(const std::string& text, const std::string& option);

// A non-negative integer such as a face number, strictly parsed (no sign, no
// trailing characters, fits in 64 bits); `what` names it in errors.
std::size_t parse_index(const std::string& text, const std::string& what);

// Output names "out/frame%04d.ply": exactly one %d conversion (with an
// optional zero flag and width), "%%" for a percent sign, nothing else.
// Throws naming the pattern otherwise.
void check_frame_pattern(const std::string& pattern);
std::string frame_name(const std::string& pattern, std::size_t frame);

// The files a shell pattern such as "anim/frame*.obj" names, sorted by name;
// throws when it names none.
std::vector<std::string> expand_pattern(const std::string& pattern);

// Whether two paths name one file (links resolved where they can be); false for an empty path.
bool same_path(const std::string& a, const std::string& b);

// Refuses an output path that names one of the input files, or lies inside
// one of the folders read whole (the run would destroy what it reads); empty
// paths are ignored.
void check_output_is_not_input(const std::string& output, const std::vector<std::string>& inputs,
                               const std::vector<std::string>& folders = {});
void check_outputs_are_not_inputs(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs,
                                  const std::vector<std::string>& folders = {});

// What Tables::load(spec) reads, for the checks above: its table file, or
// its folder of exact JSON tables. Throws LoadError as the load would.
struct TableInput {
  std::string file, folder;
};
TableInput table_input(const std::string& spec);

// Refuses, before the work, an output that could not be written at its end:
// a path that is a directory, or whose folder is missing, not a folder or not
// writable. Empty paths (an output not asked for) are ignored.
void check_output_can_be_written(const std::string& output);

// --boundary none|edge-only|edge-and-corner: how a mesh with boundaries is
// interpolated there; given, it overrides the mesh's `interpolateboundary` tag.
struct BoundaryOption {
  std::string text;
  void add(CLI::App& app);
  void apply(stencil_runtime::Mesh& mesh) const;
};

}  // namespace stencil_tools
