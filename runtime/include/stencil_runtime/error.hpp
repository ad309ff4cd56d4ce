#pragma once
// The runtime's one error base type: every failure the library reports is a
// stencil_runtime::Error (or one of the kinds below), with a complete message
// that names the file, face, vertex or value at fault.
#include <stdexcept>

namespace stencil_runtime {

struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A table or mesh file that cannot be read, or whose contents break its format or the limits.
struct LoadError : Error {
  using Error::Error;
};

// A mesh the runtime cannot evaluate: its topology, a valence or a face size.
struct MeshError : Error {
  using Error::Error;
};

// A request outside what a surface and its tables hold: a face, parameter, rate or position.
struct EvaluationError : Error {
  using Error::Error;
};

}  // namespace stencil_runtime
