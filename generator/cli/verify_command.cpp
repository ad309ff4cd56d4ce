// stencilgen verify TABLE.json...: re-checks curve, quad and triangle tables exactly against their scheme.
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "common/read_file.hpp"
#include "common/table_encoding.hpp"
#include "curve/curve_scheme_loader.hpp"
#include "curve/curve_table_json.hpp"
#include "curve/curve_table_verify.hpp"
#include "quad/quad_scheme_loader.hpp"
#include "quad/quad_table_json.hpp"
#include "quad/quad_table_verify.hpp"
#include "triangle/bivariate_solver.hpp"
#include "triangle/triangle_scheme_loader.hpp"
#include "triangle/triangle_table.hpp"

namespace sg::cli {

int verify(const std::vector<std::string>& files, const std::string& scheme_spec,
           const std::vector<std::string>& params) {
  int bad = 0;
  for (const std::string& file : files) {
    const std::string text = read_file(file);
    if (table_format(text) == kTriangleTableFormat) {
      // Re-solve the table and compare the serialised result byte for byte.
      const nlohmann::json doc = nlohmann::json::parse(text);
      std::vector<std::string> overrides = params;
      if (overrides.empty())
        for (const auto& [k, v] : doc.at("parameters").items()) overrides.push_back(k + "=" + v.get<std::string>());
      const TriangleScheme scheme =
          load_triangle_scheme(scheme_spec.empty() ? doc.at("scheme").get<std::string>() : scheme_spec, overrides);
      const int v = doc.at("valence").get<int>();
      const long n = doc.at("n").get<long>();
      const TriangleTable fresh = solve_triangle_table(scheme, v, n, solve_regular(scheme, 3 * n));
      if (triangle_table_to_json(fresh) == text) {
        std::cout << file << ": OK (" << scheme.name << " triangle table, valence " << v << ", n = " << n << "; "
                  << (fresh.exact ? "exact" : "high precision") << "; equal to the re-solved table in every digit)\n";
      } else {
        ++bad;
        std::cout << file << ": FAIL: differs from the re-solved table (scheme '" << scheme.name << "', valence " << v
                  << ", n = " << n << ")\n";
      }
      continue;
    }
    if (table_format(text) == kQuadTableFormat) {
      const std::string name = nlohmann::json::parse(text).value("scheme", "");
      std::vector<std::string> overrides = params;
      if (overrides.empty())
        for (const auto& [k, v] : nlohmann::json::parse(text).at("parameters").items())
          overrides.push_back(k + "=" + v.get<std::string>());
      const QuadScheme scheme = load_quad_scheme(scheme_spec.empty() ? name : scheme_spec, overrides);
      const auto failures = verify_quad_table_json(text, file, scheme);
      if (failures.empty())
        std::cout << file << ": OK (" << scheme.name << " surface; every stencil equals the re-solved one exactly)\n";
      else
        ++bad;
      for (const auto& f : failures) std::cout << file << ": FAIL: " << f << "\n";
      continue;
    }
    const CurveTable table = curve_table_from_json(text, file);
    std::vector<std::string> overrides = params;
    if (overrides.empty())
      for (const auto& [k, v] : table.parameters) overrides.push_back(k + "=" + to_string(v));
    const CurveScheme scheme = load_curve_scheme(scheme_spec.empty() ? table.scheme : scheme_spec, overrides);
    const auto failures = verify_curve_table(table, scheme);
    if (failures.empty()) {
      std::size_t values = 0;
      for (const auto& f : table.functions) values += f.values.size();
      std::cout << file << ": OK (" << table.scheme << ", n = " << table.n << ", " << values
                << " exact values; scaling relations, partition of unity and symmetry hold exactly)\n";
    } else {
      ++bad;
      for (const auto& f : failures) std::cout << file << ": FAIL: " << f << "\n";
    }
  }
  return bad == 0 ? 0 : 1;
}

}  // namespace sg::cli
