// Loading the exact JSON surface tables (a directory written by stencilgen:
// v<V>/n<N>.json and regular/n<2N>.json) into the same in-memory form as the
// binary file. Exact rationals become doubles; the binary file is the fast path.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "stencil_runtime/surface_table.hpp"

namespace stencil_runtime {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// An integer of any length as mantissa * 10^exponent (19 significant digits).
struct Decimal {
  long double mantissa = 0;
  long exponent = 0;
};

Decimal parse_integer(const std::string& s, const std::string& origin) {
  std::size_t i = 0;
  const bool negative = !s.empty() && s[0] == '-';
  if (negative || (!s.empty() && s[0] == '+')) ++i;
  if (i == s.size()) throw LoadError(origin + ": '" + s + "' is not an integer");
  Decimal d;
  std::size_t used = 0;
  for (std::size_t k = i; k < s.size(); ++k) {
    if (s[k] < '0' || s[k] > '9') throw LoadError(origin + ": '" + s + "' is not an integer");
    if (used < 19) {
      d.mantissa = d.mantissa * 10 + (s[k] - '0');
      ++used;
    } else {
      ++d.exponent;
    }
  }
  if (negative) d.mantissa = -d.mantissa;
  return d;
}

double ratio(const std::string& num, const std::string& den, const std::string& origin) {
  const Decimal n = parse_integer(num, origin), d = parse_integer(den, origin);
  if (d.mantissa == 0) throw LoadError(origin + ": zero denominator");
  return static_cast<double>(n.mantissa / d.mantissa * std::pow(10.0L, static_cast<long double>(n.exponent - d.exponent)));
}

double rational(const std::string& text, const std::string& origin) {
  const auto slash = text.find('/');
  return slash == std::string::npos ? ratio(text, "1", origin) : ratio(text.substr(0, slash), text.substr(slash + 1), origin);
}

json read_json(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw LoadError(file.string() + ": cannot open");
  try {
    return json::parse(in);
  } catch (const json::exception& e) {
    throw LoadError(file.string() + ": not valid JSON: " + e.what());
  }
}

}  // namespace

SurfaceTables SurfaceTables::load_json_directory(const std::string& dir, std::uint64_t expected_hash) {
  SurfaceTables t;
  std::map<int, std::map<int, fs::path>> files;  // valence -> rate -> file
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_directory() || name.size() < 2 || name[0] != 'v') continue;
    const int v = std::atoi(name.c_str() + 1);
    for (const auto& f : fs::directory_iterator(entry.path())) {
      const std::string fn = f.path().filename().string();
      if (fn.size() > 6 && fn[0] == 'n' && f.path().extension() == ".json") files[v][std::atoi(fn.c_str() + 1)] = f.path();
    }
  }
  if (files.empty()) throw LoadError(dir + ": no v<V>/n<N>.json surface tables here");
  for (const auto& [v, by_rate] : files) {
    std::vector<int> rates;
    for (const auto& [n, path] : by_rate) rates.push_back(n);
    if (t.rates_.empty()) t.rates_ = rates;
    if (rates != t.rates_)
      throw LoadError(dir + ": valence " + std::to_string(v) + " has a different set of rates than valence " +
                      std::to_string(files.begin()->first));
  }
  bool first = true;
  for (const auto& [v, by_rate] : files) {
    Valence val;
    val.valence = v;
    val.points = points(v);
    for (const auto& [n, path] : by_rate) {
      const std::string origin = path.string();
      const json doc = read_json(path);
      try {
        if (doc.at("format") != "stencilgen-surface-table" || doc.at("version") != 1)
          throw LoadError(origin + ": not a version 1 stencilgen surface table");
        if (doc.at("valence") != v || doc.at("n") != n || doc.at("points") != val.points)
          throw LoadError(origin + ": valence, rate or point count does not match the file name");
        const std::uint64_t hash = std::stoull(doc.at("scheme_hash").get<std::string>(), nullptr, 16);
        if (first) {
          t.hash_ = hash;
          if (expected_hash != 0 && hash != expected_hash) throw LoadError(origin + ": made from a different scheme (hash mismatch)");
          const json& rules = doc.at("rules");
          t.face_corner_ = rational(rules.at("face_corner"), origin);
          t.edge_end_ = rational(rules.at("edge_end"), origin);
          t.edge_wing_ = rational(rules.at("edge_wing"), origin);
          first = false;
        } else if (hash != t.hash_) {
          throw LoadError(origin + ": made from a different scheme than the other tables in " + dir);
        }
        if (doc.at("rules").contains("polygon")) {
          const json& pg = doc.at("rules").at("polygon");
          t.has_polygon_ = true;
          t.polygon_edge_end_ = rational(pg.at("edge_end"), origin);
          t.polygon_edge_face_ = rational(pg.at("edge_face_point"), origin);
          for (const auto& [key, r] : pg.at("vertex").items()) {
            const int rv = std::stoi(key);
            if (!t.polygon_vertex_rule(rv))
              t.polygon_rules_.push_back({rv, rational(r.at(0), origin), rational(r.at(1), origin), rational(r.at(2), origin)});
          }
        }
        for (const auto& [key, r] : doc.at("rules").at("vertex").items()) {
          const int rv = std::stoi(key);
          if (!t.vertex_rule(rv))
            t.rules_.push_back({rv, rational(r.at(0), origin), rational(r.at(1), origin), rational(r.at(2), origin)});
        }
        if (val.reflection.empty())
          for (const auto& x : doc.at("reflection")) val.reflection.push_back(x.get<std::uint32_t>());
        for (const char* kind : {"nodes", "centres"}) {
          const json& list = doc.at(kind);
          const std::size_t side = kind[0] == 'n' ? static_cast<std::size_t>(n + 1) : static_cast<std::size_t>(n);
          if (list.size() != side * (side + 1) / 2) throw LoadError(origin + ": wrong number of " + kind);
          std::vector<std::uint32_t> index;
          for (const json& e : list) {
            const std::string den = e.at("denominator");
            const json& nums = e.at("numerators");
            if (nums.size() != static_cast<std::size_t>(val.points)) throw LoadError(origin + ": a stencil has the wrong length");
            index.push_back(static_cast<std::uint32_t>(val.weights.size() / static_cast<std::size_t>(val.points)));
            for (const json& x : nums) val.weights.push_back(ratio(x.get<std::string>(), den, origin));
          }
          (kind[0] == 'n' ? val.nodes : val.centres).push_back(std::move(index));
        }
      } catch (const json::exception& e) {
        throw LoadError(origin + ": malformed surface table (" + e.what() + ")");
      }
    }
    if (val.reflection.size() != static_cast<std::size_t>(val.points)) throw LoadError(dir + ": bad reflection permutation");
    if (v != 4) t.valences_.push_back(std::move(val));
  }
  // The regular patch: the curve on the grid 2n.
  for (int n : t.rates_) {
    const fs::path path = fs::path(dir) / "regular" / ("n" + std::to_string(2 * n) + ".json");
    const json doc = read_json(path);
    try {
      std::map<long, double> values;
      for (const auto& [key, value] : doc.at("functions").at(0).at("values").items()) {
        const auto slash = key.find('/');
        const long p = std::stol(key.substr(0, slash)), q = slash == std::string::npos ? 1 : std::stol(key.substr(slash + 1));
        values[p * 2 * n / q] = rational(value.get<std::string>(), path.string());
      }
      const long lo = values.empty() ? 0 : values.begin()->first, hi = values.empty() ? -1 : values.rbegin()->first;
      std::vector<double> dense(static_cast<std::size_t>(hi - lo + 1), 0.0);
      for (const auto& [k, x] : values) dense[static_cast<std::size_t>(k - lo)] = x;
      t.regular_first_.push_back(lo);
      t.regular_.push_back(std::move(dense));
    } catch (const json::exception& e) {
      throw LoadError(path.string() + ": malformed curve table (" + e.what() + ")");
    }
  }
  t.index_rates();
  return t;
}

}  // namespace stencil_runtime
