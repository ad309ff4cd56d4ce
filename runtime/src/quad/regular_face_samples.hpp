#pragma once
// A regular quad face's n^2 cell centres as a tensor product: rows
// R[q][i] = sum_c w_i[c] P(c, q) and their slopes D[q][i] = sum_c w'_i[c] P(c, q)
// once per face, then at centre (i, j) the position sum_q w_j[q] R[q][i], and
// d/dx = sum_q w_j[q] D[q][i], d/dy = sum_q w'_j[q] R[q][i] for the unit normal.
// The tangents and normals of a row of samples are made together, in arrays,
// so that their sums, cross products, square roots and divisions run as vector
// instructions. Positions equal regular_centres' bit for bit; a normal is
// unit_cross's to an ulp of a double (one division where it has three; a
// tangent pair too short for that formula takes unit_cross itself).
#include <array>
#include <vector>

#include "stencil_runtime/mesh.hpp"
#include "quad_patch.hpp"

namespace stencil_runtime {

struct RegularFaceScratch {
  std::vector<double> columns, rows, slopes;  // by component (regular_face_samples.cpp)
  std::vector<double> row;  // a row's tangents and cross products, component by component
};

// w, dw: the n cell-centre weights (4 each) of the uniform cubic rows and of
// their slopes at rate n. positions may be null (normals alone).
void regular_face_samples(const QuadPatch& patch, const double* w, const double* dw, int n, const Point* prepared,
                          std::array<float, 3>* positions, std::array<float, 3>* normals, RegularFaceScratch& scratch);

}  // namespace stencil_runtime
