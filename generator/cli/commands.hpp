#pragma once
// The stencilgen commands, one file each (generate_command.cpp, ...). Each
// prints its results on stdout, throws sg::Error on bad input and returns the
// process exit code (main.cpp turns exceptions into one-line errors).
#include <string>
#include <vector>

namespace sg::cli {

struct GenerateOptions {
  std::string scheme, rates, valences, out;
  std::vector<std::string> params;
  std::string route = "both";        // curve schemes: residue, eigen or both
  std::string precision = "double";  // surface schemes: the binary file's scalars
  std::string layout = "generated";   // quad schemes: stencils generated at load time, or stored
  bool quiet = false;
};

// Curve, quad or triangle tables, by the scheme file's type.
int generate(const GenerateOptions& options);

int verify(const std::vector<std::string>& files, const std::string& scheme_spec, const std::vector<std::string>& params);

int analyze(const std::string& scheme_spec, const std::string& valence_spec, const std::vector<std::string>& params,
            long samples);

int plot(const std::string& scheme_spec, long n, const std::string& out, const std::vector<std::string>& params);

int list();

}  // namespace sg::cli
