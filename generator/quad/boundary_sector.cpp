#include "quad/boundary_sector.hpp"

#include "base/error.hpp"
#include "base/limits.hpp"
#include "quad/chart_refiner.hpp"
#include "quad/patch_subdivision.hpp"

namespace sg {

SectorLayout::SectorLayout(const BoundarySector& s) : s_(s) {
  if (s.kind == SectorKind::Cone) throw Error("internal: a cone point's patch has the interior layout");
  if (s.faces < (s.kind == SectorKind::Dart ? 3 : 1) || s.faces > limits::kMaxValence || s.position < 0 || s.position >= s.faces)
    throw Error("internal: no boundary sector of " + std::to_string(s.faces) + " faces with face " + std::to_string(s.position));
  const bool below = s.position > 0, beside = s.position + 1 < s.faces;
  if (below) outer_.emplace_back(2, -1);
  for (auto p : {std::pair{2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}}) outer_.push_back(p);
  if (beside) outer_.emplace_back(-1, 2);
  size_ = static_cast<std::size_t>(2 * s.faces + 2) + outer_.size();
}

std::optional<std::size_t> SectorLayout::chart(int i, int j) const {
  const int p = s_.position, k = s_.faces;
  if (i == 0 && j == 0) return vertex();
  if (i == 1 && j == 0) return edge(p);
  if (i == 1 && j == 1) return face(p);
  if (i == 0 && j == 1) return edge(p + 1);
  if (i == -1 && j == 1) return p + 1 < k ? std::optional(face(p + 1)) : std::nullopt;
  if (i == -1 && j == 0) return p + 2 <= k ? std::optional(edge(p + 2)) : std::nullopt;
  if (i == 0 && j == -1) return p > 0 ? std::optional(edge(p - 1)) : std::nullopt;
  if (i == 1 && j == -1) return p > 0 ? std::optional(face(p - 1)) : std::nullopt;
  for (std::size_t t = 0; t < outer_.size(); ++t)
    if (outer_[t] == std::pair{i, j}) return static_cast<std::size_t>(2 * k + 2) + t;
  return std::nullopt;
}

namespace {

class SectorRefiner final : public ChartRefiner {
 public:
  SectorRefiner(const QuadScheme& s, const SectorLayout& layout)
      : ChartRefiner(s, true, layout.bottom_boundary(), layout.left_boundary()), layout_(layout) {}

  // Refined B, e_j or f_j.
  SparseRow one_ring(std::size_t h) override {
    const SectorLayout& L = layout_;
    const int k = L.sector().faces;
    if (h == SectorLayout::vertex()) {
      if (L.sector().kind == SectorKind::Corner) {
        row_.add(L.vertex(), 1);
      } else if (L.sector().kind == SectorKind::Dart) {  // the smooth rule at valence k; e_k is e_0 again
        const VertexRule r = s_.vertex_rule(k);
        row_.add(L.vertex(), r.centre);
        for (int j = 0; j < k; ++j) row_.add(L.edge(j), r.edge), row_.add(L.face(j), r.face);
      } else {  // the boundary curve's vertex rule over e_0, B, e_k
        row_.add(L.edge(0), curve_[4]), row_.add(L.vertex(), curve_[2]), row_.add(L.edge(k), curve_[0]);
      }
    } else if (h <= static_cast<std::size_t>(k + 1)) {  // e_j: edge B-e_j
      const int j = static_cast<int>(h) - 1;
      if (j == 0) {
        row_.add(L.vertex(), curve_[3]), row_.add(L.edge(0), curve_[1]);
      } else if (j == k) {
        row_.add(L.vertex(), curve_[3]), row_.add(L.edge(k), curve_[1]);
      } else {  // between the faces j-1 and j
        row_.add(L.vertex(), s_.edge_end), row_.add(L.edge(j), s_.edge_end);
        for (std::size_t w : {L.edge(j - 1), L.face(j - 1), L.edge(j + 1), L.face(j)}) row_.add(w, s_.edge_wing);
      }
    } else {  // f_j: face (B, e_j, f_j, e_{j+1})
      const int j = static_cast<int>(h) - k - 2;
      for (std::size_t c : {L.vertex(), L.edge(j), L.face(j), L.edge(j + 1)}) row_.add(c, s_.face_corner);
    }
    return row_.take();
  }

 private:
  std::optional<std::size_t> chart(int i, int j) const override { return layout_.chart(i, j); }
  const SectorLayout& layout_;
};

}  // namespace

PatchSubdivision build_sector_subdivision(const QuadScheme& scheme, const BoundarySector& sector) {
  if (sector.kind == SectorKind::Cone) {
    if (sector.faces < 3 || sector.faces > limits::kMaxValence || sector.position != 0)
      throw Error("internal: no cone point of valence " + std::to_string(sector.faces) + " with face " +
                  std::to_string(sector.position));
    PatchSubdivision out = build_patch_subdivision(scheme, sector.faces, VertexRule{Rational(1), Rational(0), Rational(0)});
    out.reflection.clear();  // sectors are stored whole
    return out;
  }
  const SectorLayout L(sector);
  SectorRefiner refine(scheme, L);
  PatchSubdivision out;
  out.points = L.size();
  out.extraordinary_child.resize(L.size());
  const std::size_t ring = static_cast<std::size_t>(2 * sector.faces + 2);
  for (std::size_t h = 0; h < ring; ++h) out.extraordinary_child[h] = refine.one_ring(h);
  for (std::size_t t = 0; t < L.outer().size(); ++t) out.extraordinary_child[ring + t] = refine.at(L.outer()[t].first, L.outer()[t].second);
  out.regular_children = refine.regular_children();
  return out;
}

std::vector<BoundarySector> boundary_sectors(int max_faces, bool sharp) {
  std::vector<BoundarySector> out;
  for (SectorKind kind : {SectorKind::Crease, SectorKind::Corner, SectorKind::Dart}) {
    if (kind != SectorKind::Crease && !sharp) continue;
    for (int k = kind == SectorKind::Dart ? 3 : 1; k <= max_faces; ++k) {
      if (k == (kind == SectorKind::Corner ? 1 : 2)) continue;  // regular boundary patches (phantom points)
      for (int p = 0; p < k; ++p) out.push_back({kind, k, p});
    }
  }
  if (sharp)
    for (int k = 3; k <= max_faces; ++k) out.push_back({SectorKind::Cone, k, 0});
  return out;
}

}  // namespace sg
