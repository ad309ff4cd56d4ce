#pragma once
// Loads the compact binary triangle tables (*.sgt) written by stencilgen for a
// triangle scheme (Loop or sqrt(3); format in docs/table-format.md). For each
// stored valence (6 is the regular patch) it gives the stencils of the patch
// triangle (EV, e_0, e_1) at the grid nodes (i/n, j/n), i + j <= n, and at the
// "up" and "down" centres of the grid's small triangles, for every stored rate
// n. A stencil's weights go with the valence's layout: control point h is the
// sector-chart position layout(v)[h] = [sector, a, b] around the EV. Doubles only.
//
// sqrt(3) tables hold, for each valence other than 6, three more regions: the
// "band" triangles of the EV's second ring, where its vertex rule still
// reaches. In sector 0's frame, corners counter-clockwise: region 1 =
// (1,0),(2,0),(2,1); 2 = (1,0),(2,1),(1,1); 3 = (1,1),(2,1),(2,2); each has its
// own layout. Region 0 is the patch (EV, e_0, e_1).
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <optional>
#include <vector>

#include "patch_kind.hpp"
#include "sparse_rows.hpp"
#include "stencil_runtime/error.hpp"

namespace stencil_runtime {

namespace detail {
class BinaryReader;
}

enum class TriangleRefinement { Loop = 0, Sqrt3 = 1 };

struct ChartPoint {
  int sector = 0;
  int a = 0, b = 0;  // a (1,0) + b (1,1) in sector `sector`'s frame; [0,0,0] is the EV
};

// One cell of a patch after one composite step of the scheme (version 3
// tables; docs/table-format.md): the patch kind that evaluates it, and its
// control points (rows: one per point of the kind's layout) over the parent's.
struct TriangleChild {
  int valence = 6;
  int region = 0;
  int rotation = 0;  // the cell's corner at the kind's corner 0 (as TrianglePatch::rotation)
  SparseRows rows;
};

class TriangleTables {
 public:
  // Throws LoadError naming the file (missing, truncated, bad magic, version,
  // checksum, a count, index, rate or valence outside its limits, or a scheme
  // hash other than a nonzero `expected_hash`).
  static TriangleTables load(const std::string& path, std::uint64_t expected_hash = 0);
  bool single_precision() const { return single_precision_; }

  std::uint64_t scheme_hash() const { return hash_; }
  TriangleRefinement refinement() const { return refinement_; }
  // Loop's edge rule (3/8 on the ends, 1/8 on the opposite corners); 0 for sqrt(3).
  double edge_end() const { return edge_end_; }
  double edge_opposite() const { return edge_opposite_; }
  // The rule along a crease (the scheme's crease curve), when the scheme has one:
  // new vertex = centre * old + neighbour * each crease neighbour; edge points are midpoints.
  struct CreaseRule {
    double centre = 0, neighbour = 0;
  };
  const std::optional<CreaseRule>& crease() const { return crease_; }
  // The vertex rule's weight per neighbour at valence v (the old vertex keeps
  // 1 - v * weight); false when the table does not hold valence v.
  bool neighbour_weight(int valence, double& weight) const;

  const std::vector<int>& rates() const { return rates_; }
  bool has_rate(int n) const { return rate_slot(n) >= 0; }
  std::vector<int> valences() const;  // 6 included
  bool has_valence(int v) const { return find(v) != nullptr; }
  bool exact(int valence) const { return data(valence).exact; }
  double residual(int valence) const { return data(valence).residual; }
  // 1, or 4 where the valence has band regions.
  int regions(int valence) const { return static_cast<int>(data(valence).regions.size()); }
  const std::vector<ChartPoint>& layout(int valence, int region = 0) const { return region_data(valence, region).layout; }

  // Weights over layout(valence) at node (i/n, j/n), up centre
  // ((3i+1)/(3n), (3j+1)/(3n)) (i + j <= n-1) or down centre
  // ((3i+2)/(3n), (3j+2)/(3n)) (i + j <= n-2). Throws EvaluationError for a
  // valence, rate or index the table does not hold.
  const double* node_weights(int valence, int n, int i, int j) const;
  const double* up_weights(int valence, int n, int i, int j) const;
  const double* down_weights(int valence, int n, int i, int j) const;

  // The patch subdivision, for evaluation at any parameter (version 3 tables;
  // false for version 2). Each region of each valence splits into
  // dilation()^2 cells (Loop 4, sqrt(3) 9), in the order of docs/table-format.md.
  bool has_descent() const { return descent_; }
  int dilation() const { return refinement_ == TriangleRefinement::Loop ? 2 : 3; }
  const std::vector<TriangleChild>& children(int valence, int region) const { return region_data(valence, region).children; }
  // The tangent stencils at the extraordinary vertex of valence `valence`'s
  // patch (region 0): t_u.P x t_v.P is along the normal there, as du x dv next
  // to it. Null when the tables hold none (before version 4, valence 6, or a
  // subdominant eigenvalue that is not a real double one).
  const std::vector<double>* tangent_u(int valence) const;
  const std::vector<double>* tangent_v(int valence) const;
  // Whether every child weight is >= 0 (with the rules' weights: the limit over a cell lies in the hull of its points).
  bool children_nonnegative() const { return children_nonnegative_; }
  // The regular patch's basis as polynomials (Loop: degree 4), 0 when it is
  // not one; per point h of layout(6), the coefficients of u^e v^f at
  // polynomial()[h * terms + k], k running over f = 0..d, e = 0..d-f.
  int polynomial_degree() const { return degree_; }
  const std::vector<double>& polynomial() const { return polynomial_; }

  // Loop's boundary sectors (version 7; docs/table-format.md, "Loop boundary
  // sectors"): the patch of a face at a boundary vertex in k faces (or a
  // corner), the face at position p. Each is a patch kind of its own, named by
  // its code sector_kind(key) (patch_kind.hpp), which the lookups above and
  // below take as their valence: layout(code) is its wedge chart ([sector, a,
  // b], sectors 0..k), children(code, 0) its cells, tangent_u/v(code) its
  // tangent stencils where it has a tangent plane. Its stencils are made from
  // these, one rate on that rate's first grid(code, n), by the recursion the
  // generator solves exactly.
  std::optional<int> sector_code(const SectorKey& key) const;
  static bool is_sector_code(int valence) { return is_sector_kind(valence); }
  const SectorKey& sector(int code) const;
  bool has_sectors() const { return !sectors_.empty(); }
  // How far the sector's surface may reach beyond its control points' box:
  // its child at B has weights >= 0 (its points stay in their hull), and each
  // regular cell's points are affine combinations of the sector's whose
  // negative weights (the phantoms beyond the boundary) sum to at most this
  // much, so every cell's points, and so its surface (the box spline's basis
  // is >= 0), lie in the box widened by this times its extent on each side.
  // Infinite where the child at B has a negative weight.
  double sector_spread(int code) const;

  // Tangent stencils at a patch's vertex as stored (below the public interface: the reader's).
  struct TangentData {
    std::vector<double> u, v;
    double eigenvalue = 0, residual = 0;
  };

  // The same lookups with the valence and rate resolved once (a face's
  // tessellation asks for n^2 stencils of one grid).
  enum class GridPoint { Node = 0, Up = 1, Down = 2 };
  class Grid {
   public:
    // Throws EvaluationError for an index outside the patch triangle.
    const double* weights(GridPoint kind, long i, long j) const;
    // The derivative stencils along the patch's u and v at the same point, for
    // the regular patch: stored (sqrt(3), version 6) or made at load from the
    // regular polynomial (Loop); false for the other patches and older files.
    bool derivative_weights(GridPoint kind, long i, long j, const double*& du, const double*& dv) const;
    // The value, du and dv stencils at the same point together, without the
    // entries where all three are zero (sqrt(3)'s regular basis reaches 2.5
    // rings, so about a third of a point's 27 are): point column[k] has the
    // weights wuv[3k] (value), wuv[3k + 1] (du) and wuv[3k + 2] (dv), k < count.
    // One pass over the points gives a sample's position and derivatives; the
    // value's sum is bit-identical to the dense one's (its skipped weights are
    // zeros). What the tessellation's normals sum; false where
    // derivative_weights is.
    struct SparseJet {
      const std::uint32_t* column = nullptr;
      const double* wuv = nullptr;
      std::size_t count = 0;
    };
    bool sparse_jet(GridPoint kind, long i, long j, SparseJet& out) const;
    bool has_sparse_jets() const { return sparse_start_ != nullptr; }

   private:
    friend class TriangleTables;
    std::size_t stencil(GridPoint kind, long i, long j) const;  // its index among the region's stencils
    std::size_t offset(GridPoint kind, long i, long j) const { return stencil(kind, i, j) * points_; }
    const double* weights_ = nullptr;
    const double* du_ = nullptr;
    const double* dv_ = nullptr;
    const std::uint32_t* sparse_start_ = nullptr;
    const std::uint32_t* sparse_column_ = nullptr;
    const double* sparse_wuv_ = nullptr;
    std::size_t points_ = 0;
    const std::uint32_t* index_ = nullptr;
    long n_ = 1;
  };
  // Throws EvaluationError for a valence, region or rate the table does not hold.
  Grid grid(int valence, int n, int region = 0) const;

 private:
  struct Region {
    std::vector<ChartPoint> layout;
    std::vector<double> weights;                // stencil_count * layout.size()
    std::vector<double> du, dv;                 // the same for the derivatives (the regular patch), or empty
    // weights, du and dv without their common zeros (Grid::sparse_jet): per
    // stencil s, entries [sparse_start[s], sparse_start[s + 1]).
    std::vector<std::uint32_t> sparse_start;
    std::vector<std::uint32_t> sparse_column;
    std::vector<double> sparse_wuv;
    std::vector<std::vector<std::uint32_t>> index;  // per rate slot: nodes, ups, downs
    std::vector<TriangleChild> children;
  };
  struct Valence {
    int valence = 0;
    bool exact = true;
    double residual = 0, neighbour = 0;
    std::vector<Region> regions;
    // The tangent stencils at the extraordinary vertex over region 0's layout
    // (version 4; empty: none).
    TangentData tangents;
  };
  // One rate's stencils of a sector, made on first use.
  struct SectorRate {
    std::once_flag once;
    std::vector<double> weights;        // stencil_count * layout size
    std::vector<std::uint32_t> index;   // nodes, ups, downs (Grid::offset's order)
  };
  struct Sector {
    SectorKey key;
    std::vector<double> limit;  // W(0) over the layout
    double spread = 0;          // sector_spread
    // The layout, cells and tangents as a valence's (its region has no weights).
    std::unique_ptr<Valence> data = std::make_unique<Valence>();
    std::vector<std::unique_ptr<SectorRate>> rates;  // per rate slot
  };
  const Sector* find_sector(int code) const;
  // The sector's stencils at rate slot `slot` (expand on first use; EvaluationError beyond the size budget).
  const SectorRate& sector_rate(const Sector& s, int slot) const;
  static void read_sectors(detail::BinaryReader& r, const std::function<std::size_t()>& left, TriangleTables& t);
  const Valence* find(int v) const;
  const Valence& data(int v) const;  // throws EvaluationError
  const Region& region_data(int v, int region) const;  // throws EvaluationError
  int rate_slot(int n) const;

  std::uint64_t hash_ = 0;
  bool single_precision_ = false;  // the binary file's weights are float32
  TriangleRefinement refinement_ = TriangleRefinement::Loop;
  double edge_end_ = 0, edge_opposite_ = 0;
  std::optional<CreaseRule> crease_;
  std::vector<int> rates_;
  std::vector<int> slot_of_rate_;
  std::vector<Valence> valences_;
  std::vector<Sector> sectors_;
  std::unordered_map<int, std::size_t> sector_at_;  // code -> position in sectors_
  bool descent_ = false, children_nonnegative_ = true;
  int degree_ = 0;
  std::vector<double> polynomial_;
};

}  // namespace stencil_runtime
