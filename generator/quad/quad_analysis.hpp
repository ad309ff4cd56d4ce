#pragma once
// Numerical smoothness analysis of a quad scheme's extraordinary rules at one
// valence (Reif's conditions): the spectrum of the local subdivision matrix on
// the two-ring (6v+1 points, which holds every patch around the vertex) and the
// characteristic map, sampled through the exact patch stencils.
#include <complex>
#include <string>
#include <vector>

#include "quad/quad_scheme.hpp"

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

// `samples`: the characteristic map is sampled on the grid (1/samples) of every sector.
SmoothnessReport analyse_quad_valence(const QuadScheme& scheme, int valence, long samples = 32);

std::string format_report(const SmoothnessReport& r);

}  // namespace sg
