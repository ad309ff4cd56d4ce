#include "stencil_runtime/tables.hpp"

#include <algorithm>
#include <filesystem>

#include "quad_tables.hpp"
#include "triangle_tables.hpp"

namespace stencil_runtime {

namespace fs = std::filesystem;

namespace {

// The table file behind `spec`: the file itself, the one .sgs or .sgt file in
// a directory, or the directory when it holds exact quad JSON tables.
fs::path table_file(const std::string& spec) {
  fs::path p = fs::path(spec).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();  // "tables/nonpoly/"
  std::error_code ec;
  if (fs::is_regular_file(p, ec)) return p;
  if (!fs::is_directory(p, ec)) {
    if (fs::exists(p, ec)) throw LoadError(spec + ": not a table file (a regular .sgs or .sgt file) nor a directory");
    throw LoadError(spec + ": no such table file or directory");
  }
  fs::path found;
  for (const auto& e : fs::directory_iterator(p, ec))
    if (e.path().extension() == ".sgs" || e.path().extension() == ".sgt") {
      if (!found.empty()) throw LoadError(spec + ": holds several table files (.sgs, .sgt); name one");
      found = e.path();
    }
  if (found.empty() && fs::is_directory(p / "regular", ec)) return p;  // exact JSON tables
  if (found.empty())
    throw LoadError(spec + ": no .sgs or .sgt table file here, nor exact JSON tables (folders 'regular' and "
                           "v<V>/ of n<N>.json files); make them with: stencilgen --scheme nonpoly --valence 3-8 --n 24 --out tables, or "
                           "--scheme loop");
  return found;
}

}  // namespace

Tables::Tables() = default;
Tables::~Tables() = default;

std::string Tables::file_of(const std::string& path) { return table_file(path).string(); }

std::shared_ptr<const Tables> Tables::load(const std::string& path, std::uint64_t expected_hash) {
  const fs::path file = table_file(path);
  std::shared_ptr<Tables> t(new Tables());
  t->source_ = file.string();
  if (fs::is_directory(file)) {
    t->family_ = SchemeFamily::Quad;
    t->quad_ = std::make_unique<QuadTables>(QuadTables::load_json_directory(file.string(), expected_hash));
    t->scheme_ = t->quad_->scheme_name();
  } else if (file.extension() == ".sgt") {
    t->family_ = SchemeFamily::Triangle;
    t->triangle_ = std::make_unique<TriangleTables>(TriangleTables::load(file.string(), expected_hash));
    t->scheme_ = file.stem().string();
  } else if (file.extension() == ".sgs") {
    t->family_ = SchemeFamily::Quad;
    t->quad_ = std::make_unique<QuadTables>(QuadTables::load_binary(file.string(), expected_hash));
    t->scheme_ = t->quad_->scheme_name();
  } else {
    throw LoadError(file.string() + ": not a surface table (expected a .sgs or .sgt file, or a directory of them)");
  }
  if (t->scheme_.empty()) t->scheme_ = file.stem().string();
  return t;
}

const QuadTables& Tables::quad() const {
  if (!quad_) throw EvaluationError(source_ + ": holds a triangle scheme's tables, not a quad scheme's");
  return *quad_;
}

const TriangleTables& Tables::triangle() const {
  if (!triangle_) throw EvaluationError(source_ + ": holds a quad scheme's tables, not a triangle scheme's");
  return *triangle_;
}

std::uint64_t Tables::scheme_hash() const { return quad_ ? quad_->scheme_hash() : triangle_->scheme_hash(); }

const std::vector<int>& Tables::rates() const { return quad_ ? quad_->rates() : triangle_->rates(); }

bool Tables::polynomial_regular() const {
  if (quad_) return quad_->descent() && quad_->descent()->degree > 0;
  return triangle_->has_descent() && triangle_->polynomial_degree() > 0;
}

bool Tables::single_precision() const { return quad_ ? quad_->single_precision() : triangle_->single_precision(); }

int Tables::dilation() const { return quad_ ? 2 : triangle_->dilation(); }

bool Tables::has_rate(int n) const { return quad_ ? quad_->has_rate(n) : triangle_->has_rate(n); }

int Tables::rate_at_least(int wanted) const {
  const std::vector<int>& r = rates();
  const auto it = std::lower_bound(r.begin(), r.end(), wanted);
  return it == r.end() ? r.back() : *it;
}

std::vector<int> Tables::valences() const {
  std::vector<int> v = quad_ ? quad_->valences() : triangle_->valences();
  if (quad_) v.push_back(4);
  std::sort(v.begin(), v.end());
  return v;
}

bool Tables::has_valence(int valence) const { return quad_ ? quad_->has_valence(valence) : triangle_->has_valence(valence); }

}  // namespace stencil_runtime
