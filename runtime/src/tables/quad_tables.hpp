#pragma once
// A quad scheme's tables (*.sgs, or a directory of its exact JSON tables; format
// in docs/table-format.md): the stencils of the regular patch and of the patch
// round an extraordinary vertex, at the grid nodes (i/n, j/n) and cell centres
// ((2i+1)/(2n), (2j+1)/(2n)) of every stored rate n, and the scheme's
// subdivision rules. Control point order: docs/table-format.md (regular: 16
// points row by row; extraordinary: 2v+8 points, EV first). Doubles only.
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "patch_kind.hpp"
#include "sparse_rows.hpp"
#include "stencil_runtime/error.hpp"

namespace stencil_runtime {

// The scheme's own subdivision of a patch (version 4 tables), for evaluation at
// any parameter: see QuadTables::descent() and docs/runtime.md.
struct QuadDescent {
  // The regular curve's mask a_i, i = mask_first ..: p'_k = sum_j a_{k - 2j} p_j.
  std::int64_t mask_first = 0;
  std::vector<double> mask;
  bool mask_nonnegative = false;        // then the limit lies in the hull of the control points
  bool derivative_nonnegative = false;  // then its derivatives lie in the hull of their differences
  // The regular basis on [0, 1] as polynomials (degree 0: not polynomial):
  // basis[p + 1][e] is the coefficient of t^e of phi(t - p), p = -1..2.
  int degree = 0;
  std::vector<std::vector<double>> basis;
  struct Valence {
    bool nonnegative = false;      // every weight of A0 and of the regular children
    SparseRows ev_child;           // A0: 2v+8 rows over the patch's 2v+8 points
    SparseRows regular_children[3];  // 16 rows each; children at offsets (1,0), (0,1), (1,1) in half-patch units
    // The tangent plane at the extraordinary vertex: t.P for t in {tangent_u,
    // tangent_v} span it, along the patch's u and v edges (not parametric
    // derivatives; empty when the tables hold none).
    std::vector<double> tangent_u, tangent_v;
    double tangent_eigenvalue = 0, tangent_residual = 0;
    // The other eigenvalue of the pair (boundary sectors, where the two may
    // differ: docs/table-format.md; equal to tangent_eigenvalue otherwise).
    double tangent_second_eigenvalue = 0;
  };
};

class QuadTables {
 public:
  // Throws LoadError naming the file (missing, truncated, bad magic, version,
  // checksum, a count, index, rate or valence outside its limits, or a scheme
  // hash other than a nonzero `expected_hash`).
  static QuadTables load_binary(const std::string& path, std::uint64_t expected_hash = 0);
  bool single_precision() const { return single_precision_; }
  // A directory of exact JSON tables as stencilgen writes them (v<V>/n<N>.json,
  // regular/n<2N>.json); rationals become the nearest double.
  static QuadTables load_json_directory(const std::string& dir, std::uint64_t expected_hash = 0);

  std::uint64_t scheme_hash() const { return hash_; }
  const std::string& scheme_name() const { return name_; }

  // The scheme's subdivision rules, as stored (double).
  struct VertexRule {
    int valence = 4;
    double centre = 0, edge = 0, face = 0;
  };
  double face_corner() const { return face_corner_; }
  double edge_end() const { return edge_end_; }
  double edge_wing() const { return edge_wing_; }
  // nullptr when the table has no rule for that valence.
  const VertexRule* vertex_rule(int valence) const;
  // Rules for one step on a mesh with arbitrary polygons (scheme-format.md):
  // face point = centroid; edge point = polygon_edge_end * ends +
  // polygon_edge_face * the two face points; vertex point = centre * old +
  // edge * mean edge midpoint + face * mean face point (VertexRule fields).
  bool has_polygon_rules() const { return has_polygon_; }
  double polygon_edge_end() const { return polygon_edge_end_; }
  double polygon_edge_face() const { return polygon_edge_face_; }
  // OpenSubdiv's smooth triangle rule replaces Catmull-Clark's polygon edge
  // rule (1/4 each end and each face point) and is refused with MeshError for a
  // scheme with its own.
  void check_smooth_triangles() const;
  const VertexRule* polygon_vertex_rule(int valence) const;
  const std::vector<int>& rates() const { return rates_; }
  std::vector<int> valences() const;  // extraordinary valences stored (4 is the regular patch)
  bool has_rate(int n) const { return rate_slot(n) >= 0; }
  bool has_valence(int v) const;
  static int points(int kind) { return patch_points(kind); }  // any patch kind (patch_kind.hpp)
  // The boundary sectors the tables hold (version 8 binary, descent.json version 3).
  bool has_sector(const SectorKey& s) const { return find_sector(s) != nullptr; }
  // Whether they hold any sector of that rule (tables from before a rule was added hold none).
  bool has_sector_rule(SectorRule rule) const;
  std::vector<SectorKey> sectors() const;

  // The patch subdivision (binary tables of version 4; nullptr for exact JSON
  // tables without descent.json).
  const QuadDescent* descent() const { return has_descent_ ? &descent_ : nullptr; }
  // The extraordinary patch's stencils of `valence`, recomputed from the patch
  // subdivision, the regular values and the limit stencil (quad_expansion.hpp),
  // in the stored form (weights, per-rate node and centre indices).
  struct Expanded {
    std::vector<double> weights;
    std::vector<std::vector<std::uint32_t>> nodes, centres;
  };
  Expanded expand(int valence) const;
  const QuadDescent::Valence& descent(int valence) const;

  // Weights over the patch's control points (16 for the regular patch or
  // valence 4, 2v+8 otherwise, a sector's own count for a sector kind) at node
  // (i/n, j/n), 0 <= i,j <= n, or at the centre of cell (i,j), 0 <= i,j < n.
  // Throws EvaluationError for a rate, kind or index that is not in the table.
  // The first use of a boundary sector expands its stencils (every rate).
  void node_stencil(int valence, int n, int i, int j, double* weights) const;
  void centre_stencil(int valence, int n, int i, int j, double* weights) const;

  // Direct access for extraordinary patches (valence != 4) and sectors: the
  // stored weights at cell centre (i, j) of rate n in patch coordinates. When
  // `mirrored` comes back true (never for a sector, which stores every point)
  // they are the weights at (j, i): apply them to the control points permuted
  // by reflection(valence), i.e. weight h multiplies point reflection[h].
  const double* centre_weights(int valence, int n, int i, int j, bool& mirrored) const;
  // The same for every cell of one patch kind at rate n, looked up once (a
  // face's loop over its cells): at(i, j, mirrored), 0 <= i, j < n, is
  // centre_weights(valence, n, i, j, mirrored). Valid while the tables live.
  class CentreGrid {
   public:
    const double* at(int i, int j, bool& mirrored) const {
      mirrored = reflected_ && i > j;
      const long k = stored_at(reflected_, side_, mirrored ? j : i, mirrored ? i : j);
      return weights_ + static_cast<std::size_t>(index_[static_cast<std::size_t>(k)]) * points_;
    }

   private:
    friend class QuadTables;
    const double* weights_ = nullptr;
    const std::uint32_t* index_ = nullptr;
    long side_ = 0;
    std::size_t points_ = 0;
    bool reflected_ = false;
  };
  CentreGrid centre_grid(int valence, int n) const;
  // nullptr for a boundary sector, which has no reflection (and is never mirrored).
  const std::uint32_t* reflection(int valence) const {
    const auto& r = valence_data(valence).reflection;
    return r.empty() ? nullptr : r.data();
  }

  // The regular patch is a tensor product: its weight for point (p, q) at
  // (a/(2n), b/(2n)) is w(a)[p+1] * w(b)[q+1], with w(a) the four values
  // phi(a/(2n) - p), p = -1..2, written here (0 <= a <= 2n).
  void regular_weights(int n, long a, double* w4) const;
  // The same for phi' (the regular curve's derivative, version 5 tables and
  // JSON tables from this stencilgen): phi'(a/(2n) - p), p = -1..2. Throws
  // EvaluationError where the tables hold none (a curve that is not C1).
  bool has_regular_derivatives() const { return !regular_derivative_.empty(); }
  void regular_derivative_weights(int n, long a, double* w4) const;

 private:
  struct Valence {
    int valence = 0, points = 0;  // valence: the patch kind
    std::vector<std::uint32_t> reflection;
    std::vector<double> weights;  // stencil_count * points
    // Per rate slot: with a reflection (i <= j) j-major; without (sectors) every (i, j), j-major.
    std::vector<std::vector<std::uint32_t>> nodes, centres;
  };
  // A boundary sector: what generates its stencils, expanded on first use.
  struct Sector {
    SectorKey key;
    std::vector<double> limit;  // W(0)
    QuadDescent::Valence descent;
    std::unique_ptr<std::once_flag> once = std::make_unique<std::once_flag>();
    mutable std::unique_ptr<const Valence> expanded;
  };
  const Sector* find_sector(const SectorKey& s) const;
  const Valence& expanded(const Sector& s) const;
  int rate_slot(int n) const;
  int checked_slot(int n) const;  // throws EvaluationError for a rate not stored
  // Checks everything a reader filled in (rates, valences, reflections,
  // indices, rules) against the limits and fills slot_of_rate_; LoadError
  // prefixed with `origin`.
  void validate(const std::string& origin);
  // The stored half: stencil (i, j), i <= j, of a node or a centre.
  const double* stored_weights(const Valence& v, int slot, long i, long j, bool centre) const;
  // Where grid point (i, j) of a grid `side` points wide is in its index: a
  // kind with a reflection stores the points with i <= j only, by rows of j.
  static long stored_at(bool reflected, long side, long i, long j) { return reflected ? j * (j + 1) / 2 + i : j * side + i; }
  void regular_weights_at(int slot, long a, double* w4) const;
  const Valence& valence_data(int v) const;
  // Stencil at parameter (a/g, b/g), g = 2n, a and b both even (node) or both odd (centre).
  void stencil(int valence, int slot, long a, long b, bool centre, double* weights) const;

  std::uint64_t hash_ = 0;
  bool single_precision_ = false;  // the binary file's weights are float32
  std::string name_;
  double face_corner_ = 0, edge_end_ = 0, edge_wing_ = 0;
  std::vector<VertexRule> rules_;
  bool has_polygon_ = false;
  double polygon_edge_end_ = 0, polygon_edge_face_ = 0;
  std::vector<VertexRule> polygon_rules_;
  std::vector<int> rates_;
  std::vector<int> slot_of_rate_;  // rate -> slot, -1 when absent
  std::vector<std::vector<double>> regular_;  // per rate slot: phi(k/(2n)) for k = regular_first_ + ...
  std::vector<std::int64_t> regular_first_;
  std::vector<std::vector<double>> regular_derivative_;  // per rate slot: phi'(k/(2n)), empty when none
  std::vector<std::int64_t> regular_derivative_first_;
  std::vector<Valence> valences_;
  bool has_descent_ = false;
  QuadDescent descent_;
  std::vector<QuadDescent::Valence> descent_valences_;  // parallel to valences_
  std::vector<Sector> sectors_;
  std::unordered_map<int, std::size_t> sector_by_kind_;  // sector_kind(key) -> position in sectors_ (validate)
};

}  // namespace stencil_runtime
