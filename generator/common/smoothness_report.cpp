#include "common/smoothness_report.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sg {
namespace {

constexpr double kTol = 1e-9;

}  // namespace

void classify_spectrum(SmoothnessReport& r, std::vector<std::complex<double>> eigenvalues) {
  r.eigenvalues = std::move(eigenvalues);
  std::sort(r.eigenvalues.begin(), r.eigenvalues.end(), [](auto a, auto b) { return std::abs(a) > std::abs(b); });
  const auto& e = r.eigenvalues;
  r.one_simple = std::abs(e[0] - 1.0) < kTol && std::abs(e[1]) < 1 - kTol;
  r.subdominant = e[1].real();
  r.subdominant_real_double = std::abs(e[1].imag()) < kTol && std::abs(e[2].imag()) < kTol &&
                              std::abs(e[1] - e[2]) < kTol && e[1].real() > 0;
  r.next_modulus = e.size() > 3 ? std::abs(e[3]) : 0;
  r.subdominant_dominates = r.subdominant_real_double && std::abs(e[1]) > r.next_modulus + kTol;
}

std::string format_report(const SmoothnessReport& r) {
  std::ostringstream out;
  out.precision(6);
  auto yes = [](bool b) { return b ? "yes" : "NO"; };
  out << "valence " << r.valence << ": " << (r.ok() ? "OK" : "FAILS") << "\n  spectrum (" << r.eigenvalues.size()
      << " eigenvalues of the two-ring matrix, by modulus):";
  const std::size_t shown = std::min<std::size_t>(r.eigenvalues.size(), 10);
  for (std::size_t i = 0; i < shown; ++i) {
    const auto& z = r.eigenvalues[i];
    out << " " << z.real();
    if (std::abs(z.imag()) > 1e-6) out << (z.imag() > 0 ? "+" : "") << z.imag() << "i";
  }
  if (shown < r.eigenvalues.size()) out << " ...";
  out << "\n  eigenvalue 1 simple: " << yes(r.one_simple) << "\n  subdominant " << r.subdominant
      << " real and double: " << yes(r.subdominant_real_double) << "\n  subdominant > |next| = " << r.next_modulus
      << ": " << yes(r.subdominant_dominates) << "\n  characteristic map regular (" << r.cells_checked
      << " sampled triangles, " << r.cells_flipped << " flipped): " << yes(r.map_regular)
      << "\n  characteristic map injective (outer boundary winds " << r.winding << " times): " << yes(r.map_injective)
      << "\n";
  return out.str();
}

}  // namespace sg
