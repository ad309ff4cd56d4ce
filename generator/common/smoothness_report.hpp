#pragma once
// The verdict of a smoothness analysis at one valence (Reif's conditions), as
// the quad and triangle analyses (quad/quad_analysis, triangle/triangle_analysis)
// fill it and `stencilgen analyze` prints it.
#include <complex>
#include <string>
#include <vector>

namespace sg {

struct SmoothnessReport {
  int valence = 0;
  std::vector<std::complex<double>> eigenvalues;  // by decreasing modulus
  bool one_simple = false;          // 1 is an eigenvalue of multiplicity one and all others are smaller
  bool subdominant_real_double = false;
  bool subdominant_dominates = false;  // strictly larger in modulus than every eigenvalue but 1
  double subdominant = 0, next_modulus = 0;
  bool map_regular = false;   // one orientation on every sampled cell of every sector
  bool map_injective = false;  // the image of the boundary winds exactly once around 0
  long cells_checked = 0;
  long cells_flipped = 0;
  double winding = 0;        // of the outer boundary's image, in turns
  bool ok() const {
    return one_simple && subdominant_real_double && subdominant_dominates && map_regular && map_injective;
  }
};

// Fills the spectrum and its verdicts (conditions 1-3) from a matrix's eigenvalues.
void classify_spectrum(SmoothnessReport& r, std::vector<std::complex<double>> eigenvalues);

std::string format_report(const SmoothnessReport& r);

}  // namespace sg
