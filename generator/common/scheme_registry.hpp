#pragma once
// Where schemes are found: the schemes directory, the names in it by family,
// and a `--scheme` argument resolved to its file.
#include <filesystem>
#include <string>
#include <vector>

namespace sg {

// Directory searched for `--scheme NAME`: $STENCILGEN_SCHEMES_DIR, else the
// source tree's schemes/ folder.
std::filesystem::path default_schemes_dir();

enum class SchemeFamily { Any, Curve, Quad, Triangle };

// Names of the *.json files in `dir` (sorted), for listings and error messages;
// with a family, only the files whose "type" belongs to it.
std::vector<std::string> available_schemes(const std::filesystem::path& dir = default_schemes_dir(),
                                           SchemeFamily family = SchemeFamily::Any);

// A scheme name: letters, digits, '-' and '_', starting with a letter or digit,
// at most limits::kMaxNameLength characters. It names OUT/<name>/ and
// <name>.sgs, and a table's "scheme" field is looked up as one, never as a path.
bool is_scheme_name(const std::string& name);
extern const char* const kSchemeNameRule;  // the rule above, for messages

// `spec` is a path (contains '/' or ends in .json) or a scheme name looked up
// in `dir`. Throws sg::Error with the list of available schemes when the name
// is unknown, and names the spec when it is neither a name nor a readable path.
std::filesystem::path resolve_scheme_file(const std::string& spec, const std::filesystem::path& dir);

// The "type" field of a scheme file ("curve-uniform", "quad", ...), for dispatch.
std::string scheme_type(const std::string& spec, const std::filesystem::path& dir = default_schemes_dir());

}  // namespace sg
