// Fuzz targets curve_scheme, quad_scheme and triangle_scheme: a scheme file
// (docs/scheme-format.md) loaded by the loader FUZZ_SCHEME_KIND selects (set in
// fuzz/CMakeLists.txt: 1 curve, 2 quad, 3 triangle), beside copies of the
// bundled schemes (a quad scheme names its regular curve scheme, found in the
// same directory). Surface schemes' vertex rules are then evaluated at every
// valence from 3 to 16 (as stencilgen does for the valences it is asked for);
// out-of-range valences are refused with sg::Error.
#include <filesystem>

#include "fuzz_support.hpp"
#include "quad/quad_scheme_loader.hpp"
#include "common/scheme_registry.hpp"
#include "curve/curve_scheme_loader.hpp"
#include "triangle/triangle_scheme_loader.hpp"

namespace {

namespace fs = std::filesystem;

// Adapter: the entry point under test (one per target).
void load_and_use(const std::string& path) {
#if FUZZ_SCHEME_KIND == 1
  sg::load_curve_scheme(path);
#elif FUZZ_SCHEME_KIND == 2
  const sg::QuadScheme scheme = sg::load_quad_scheme(path);
  for (int v = 3; v <= 16; ++v) {
    try {
      scheme.vertex_rule(v);
      if (scheme.polygon.present) scheme.polygon_vertex_rule(v);
    } catch (const sg::Error&) {
    }
  }
#elif FUZZ_SCHEME_KIND == 3
  const sg::TriangleScheme scheme = sg::load_triangle_scheme(path);
  for (int v = 3; v <= 16; ++v) {
    try {
      scheme.exact_neighbour_weight(v);
      scheme.real_neighbour_weight(v);
    } catch (const sg::Error&) {
    }
  }
#else
#error "FUZZ_SCHEME_KIND must be 1 (curve), 2 (quad) or 3 (triangle)"
#endif
}

// scratch_dir()/schemes with a copy of every bundled scheme, made once.
const fs::path& scheme_dir() {
  static const fs::path dir = [] {
    const fs::path d = fuzz::scratch_dir() / "schemes";
    fs::create_directories(d);
    for (const auto& entry : fs::directory_iterator(fuzz::source_dir() / "schemes"))
      if (entry.path().extension() == ".json") fs::copy_file(entry.path(), d / entry.path().filename());
    return d;
  }();
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const fs::path path = scheme_dir() / "fuzzed.json";
  fuzz::write_file(path, fuzz::as_text(data, size));
  fuzz::run_expecting_errors([&] { load_and_use(path.string()); });
  return 0;
}
