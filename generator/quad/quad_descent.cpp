#include "quad/quad_descent.hpp"

#include <algorithm>
#include <iterator>
#include <mutex>

#include <tbb/parallel_for.h>

#include "algebra/real.hpp"
#include "base/error.hpp"
#include "common/tenths_progress.hpp"
#include "quad/ev_patch_solver.hpp"

namespace sg {

namespace {

bool nonnegative(const std::vector<SparseRow>& rows) {
  return std::all_of(rows.begin(), rows.end(), [](const SparseRow& r) {
    return std::all_of(r.begin(), r.end(), [](const auto& e) { return e.second >= 0; });
  });
}

bool nonnegative(const PatchSubdivision& s) {
  return nonnegative(s.extraordinary_child) &&
         std::all_of(s.regular_children.begin(), s.regular_children.end(), [](const auto& rows) { return nonnegative(rows); });
}

}  // namespace

QuadDescent quad_descent(const QuadScheme& scheme, const std::vector<int>& valences,
                         const std::vector<BoundarySector>& sectors,
                         const std::function<void(const std::string&)>& progress) {
  const CurveScheme& curve = scheme.curve;
  if (!curve.is_uniform() || curve.arity != 2) throw Error("internal: a quad scheme's regular curve must be uniform and binary");
  QuadDescent out;
  long last = 0;
  out.mask_first = curve.types[0].terms.front().shift;
  for (const Term& t : curve.types[0].terms) out.mask_first = std::min(out.mask_first, t.shift), last = std::max(last, t.shift);
  out.mask.assign(static_cast<std::size_t>(last - out.mask_first + 1), Rational(0));
  for (const Term& t : curve.types[0].terms) out.mask[static_cast<std::size_t>(t.shift - out.mask_first)] += t.coeff;
  out.mask_nonnegative = std::all_of(out.mask.begin(), out.mask.end(), [](const Rational& a) { return a >= 0; });
  // b(z) = 2 a(z) / (1 + z) by synthetic division, when 1 + z divides a(z).
  std::vector<Rational> b(out.mask.size() - 1, Rational(0));
  Rational carry = 0;
  for (std::size_t k = 0; k + 1 < out.mask.size(); ++k) {
    b[k] = out.mask[k] - carry;
    carry = b[k];
  }
  const bool divides = out.mask.back() == carry;
  out.derivative_nonnegative = divides && std::all_of(b.begin(), b.end(), [](const Rational& x) { return x >= 0; });
  out.pieces = polynomial_pieces(curve);
  std::vector<int> extraordinary;
  std::copy_if(valences.begin(), valences.end(), std::back_inserter(extraordinary), [](int v) { return v != 4; });
  std::mutex report;
  std::size_t done = 0;
  out.valences.resize(extraordinary.size());
  sg::prepare_real_limits();  // before threads first use Real (algebra/real.hpp)
  tbb::parallel_for(std::size_t(0), extraordinary.size(), [&](std::size_t k) {
    const int v = extraordinary[k];
    QuadDescent::Valence& d = out.valences[k];
    d.valence = v;
    d.subdivision = build_patch_subdivision(scheme, v);
    d.tangents = ev_tangents(scheme, v, d.subdivision, d.no_tangents);
    d.nonnegative = nonnegative(d.subdivision);
    if (progress) {
      std::lock_guard lock(report);
      progress(scheme.name + ": valence " + std::to_string(v) + " patch subdivision and tangent plane solved (" +
               std::to_string(++done) + "/" + std::to_string(extraordinary.size()) + ")");
    }
  });
  TenthsProgress sectors_done(progress, scheme.name + ": boundary, crease, corner, dart and cone sectors", sectors.size());
  out.sectors.resize(sectors.size());
  sg::prepare_real_limits();  // before threads first use Real (algebra/real.hpp)
  tbb::parallel_for(std::size_t(0), sectors.size(), [&](std::size_t k) {
    QuadDescent::Sector& d = out.sectors[k];
    d.sector = sectors[k];
    d.subdivision = build_sector_subdivision(scheme, d.sector);
    d.limit = limit_stencil(d.subdivision, scheme.name + ", " + d.sector.name());
    // The children's phantom rows (2 p - q) are extrapolations, but the limit
    // over such a child is the regular patch of its points, inside their hull
    // when the mask is non-negative: what must be non-negative for the hull
    // property is A0 (the rules themselves) and the mask.
    d.nonnegative = nonnegative(d.subdivision.extraordinary_child) && out.mask_nonnegative;
    d.tangents = sector_tangents(scheme, d.sector, d.subdivision, d.limit, d.no_tangents);
    sectors_done.done();
  });
  return out;
}

}  // namespace sg
