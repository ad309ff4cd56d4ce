#pragma once
// The exact stencil tables of one surface scheme, as stencilgen writes them: a
// quad scheme's .sgs file (nonpoly, Catmull-Clark), a triangle scheme's .sgt
// file (Loop, sqrt(3)), or a directory of a quad scheme's exact JSON tables.
// The scheme's name and family come from the tables themselves. Loaded once,
// immutable, and shared: every surface built on them holds a shared_ptr, so a
// surface can never outlive its tables.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "error.hpp"

namespace stencil_runtime {

enum class SchemeFamily { Quad, Triangle };

class QuadTables;
class TriangleTables;

class Tables {
 public:
  // `path`: a .sgs or .sgt file; a directory holding exactly one such file
  // (what `stencilgen --out DIR` writes, e.g. tables/nonpoly); or a directory
  // of exact quad JSON tables (v<V>/n<N>.json, regular/n<2N>.json). Throws
  // LoadError naming the file and the fault (missing, truncated, bad magic,
  // version, checksum, a count, index or rate out of its limits, or a scheme
  // hash other than a nonzero `expected_hash`).
  static std::shared_ptr<const Tables> load(const std::string& path, std::uint64_t expected_hash = 0);
  // What load(path) reads: the table file, or the directory of exact JSON
  // tables. Throws LoadError as load() does when there is none.
  static std::string file_of(const std::string& path);

  SchemeFamily family() const { return family_; }
  const std::string& scheme() const { return scheme_; }  // e.g. "nonpoly"
  const std::string& source() const { return source_; }  // the file or directory loaded
  std::uint64_t scheme_hash() const;
  // The stored rates, ascending.
  const std::vector<int>& rates() const;
  bool has_rate(int n) const;
  // The smallest stored rate >= wanted (the largest stored one if none is).
  int rate_at_least(int wanted) const;
  // Every stored valence, the regular one (4 for quads, 6 for triangles) included.
  std::vector<int> valences() const;
  bool has_valence(int valence) const;
  int regular_valence() const { return family_ == SchemeFamily::Quad ? 4 : 6; }
  // Corners of the faces the scheme's patches cover: 4 or 3.
  int face_corners() const { return family_ == SchemeFamily::Quad ? 4 : 3; }
  // Whether the regular patch's basis is polynomial (Catmull-Clark, Loop), so
  // that exact rows and first derivatives exist at every parameter; false for
  // the others (nonpoly, sqrt(3)) and for tables without patch subdivision data.
  bool polynomial_regular() const;
  // Whether the weights were stored as float32 (stencilgen --binary-precision
  // single): every value is then good to their rounding only, about 1e-7 of
  // the coordinates, and evaluations say so (Evaluation::exact false, a bound
  // of 2^-20 of the largest coordinate at least: an estimate, not a proof).
  bool single_precision() const;
  // The factor by which one step of the scheme's own patch subdivision scales
  // the parameters: 2, or 3 for sqrt(3)'s composite step.
  int dilation() const;

  // The family's own tables, for the family code below the public interface;
  // throw EvaluationError when the tables are of the other family.
  const QuadTables& quad() const;
  const TriangleTables& triangle() const;

  Tables(const Tables&) = delete;
  Tables& operator=(const Tables&) = delete;
  ~Tables();

 private:
  Tables();
  SchemeFamily family_ = SchemeFamily::Quad;
  std::string scheme_, source_;
  std::unique_ptr<QuadTables> quad_;
  std::unique_ptr<TriangleTables> triangle_;
};

}  // namespace stencil_runtime
