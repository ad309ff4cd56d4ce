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

// One *.json file of the schemes directory: its name (the file's stem) and
// family, or why it cannot be used (not a valid scheme file, or a "name" field
// other than the file's name: `--scheme NAME` finds the file by its name and
// writes tables named by the field, so the two must agree).
struct SchemeEntry {
  std::string name;
  SchemeFamily family = SchemeFamily::Any;
  std::string problem;  // empty when the file is a usable scheme
};
// Every *.json file in `dir`, sorted by name. Throws sg::Error naming the
// directory when it cannot be read (missing, not a directory, no access).
std::vector<SchemeEntry> scheme_catalogue(const std::filesystem::path& dir = default_schemes_dir());

// Names of the usable schemes in `dir` (sorted), for listings and error
// messages; with a family, only those whose "type" belongs to it.
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

// A scheme looked up by name (`spec` not a path) must say that name in its
// "name" field: the file is found by the one and its tables are written under
// the other, so a copy of fourpoint.json saved as mine.json and left named
// "fourpoint" would overwrite fourpoint's tables. Throws sg::Error naming
// `file`.
void check_scheme_file_name(const std::string& spec, const std::string& name, const std::filesystem::path& file);

// The "type" field of a scheme file ("curve-uniform", "quad", ...), for dispatch.
std::string scheme_type(const std::string& spec, const std::filesystem::path& dir = default_schemes_dir());

}  // namespace sg
