#include "stencil_runtime/surface_table.hpp"

#include <filesystem>
#include <stdexcept>

#include "binary_reader.hpp"

namespace stencil_runtime {

namespace {

std::vector<double> read_scalars(detail::BinaryReader& r, std::size_t count, std::uint32_t bytes, std::size_t available) {
  if (count > available / bytes) r.fail("truncated scalar block");
  std::vector<double> out(count);
  for (auto& x : out) x = bytes == 8 ? r.get<double>() : static_cast<double>(r.get<float>());
  return out;
}

std::size_t half_count(long side) { return static_cast<std::size_t>(side * (side + 1) / 2); }

}  // namespace

SurfaceTables SurfaceTables::load(const std::string& path, std::uint64_t expected_hash) {
  if (std::filesystem::is_directory(path)) return load_json_directory(path, expected_hash);
  const std::string bytes = detail::read_binary_file(path);
  detail::BinaryReader r(bytes, path);
  detail::check_envelope(bytes, r, format::kSurfaceMagic, "binary surface table");
  const auto version = r.get<std::uint32_t>();
  if (version != format::kSurfaceVersion)
    r.fail("format version " + std::to_string(version) + " is not supported (expected " +
           std::to_string(format::kSurfaceVersion) + ")");
  const auto scalar = r.get<std::uint32_t>();
  if (scalar != 4 && scalar != 8) r.fail("invalid scalar size " + std::to_string(scalar));
  SurfaceTables t;
  t.hash_ = r.get<std::uint64_t>();
  if (expected_hash != 0 && t.hash_ != expected_hash) r.fail("made from a different scheme (hash mismatch)");
  auto left = [&] { return bytes.size() - r.position(); };
  t.face_corner_ = r.get<double>();
  t.edge_end_ = r.get<double>();
  t.edge_wing_ = r.get<double>();
  const auto rule_count = r.get<std::uint32_t>();
  if (rule_count > left() / 28) r.fail("truncated rule list");
  for (std::uint32_t k = 0; k < rule_count; ++k) {
    VertexRule rule;
    rule.valence = static_cast<int>(r.get<std::uint32_t>());
    rule.centre = r.get<double>();
    rule.edge = r.get<double>();
    rule.face = r.get<double>();
    t.rules_.push_back(rule);
  }
  t.has_polygon_ = r.get<std::uint8_t>() != 0;
  if (t.has_polygon_) {
    t.polygon_edge_end_ = r.get<double>();
    t.polygon_edge_face_ = r.get<double>();
    for (const auto& rule : t.rules_) {
      VertexRule p{rule.valence, r.get<double>(), r.get<double>(), r.get<double>()};
      t.polygon_rules_.push_back(p);
    }
  }
  const auto rate_count = r.get<std::uint32_t>();
  if (rate_count > left() / 4) r.fail("truncated rate list");
  for (std::uint32_t k = 0; k < rate_count; ++k) {
    const auto n = r.get<std::uint32_t>();
    if (n == 0 || n > 100000) r.fail("invalid rate " + std::to_string(n));
    t.rates_.push_back(static_cast<int>(n));
  }
  for (std::uint32_t k = 0; k < rate_count; ++k) {
    t.regular_first_.push_back(r.get<std::int32_t>());
    const auto count = r.get<std::uint32_t>();
    t.regular_.push_back(read_scalars(r, count, scalar, left()));
  }
  const auto valence_count = r.get<std::uint32_t>();
  for (std::uint32_t k = 0; k < valence_count; ++k) {
    Valence v;
    v.valence = static_cast<int>(r.get<std::uint32_t>());
    v.points = static_cast<int>(r.get<std::uint32_t>());
    if (v.valence < 3 || v.valence > 100000 || v.points != points(v.valence)) r.fail("invalid valence header");
    const auto stencils = r.get<std::uint32_t>();
    for (int h = 0; h < v.points; ++h) {
      v.reflection.push_back(r.get<std::uint32_t>());
      if (v.reflection.back() >= static_cast<std::uint32_t>(v.points)) r.fail("invalid reflection permutation");
    }
    v.weights = read_scalars(r, static_cast<std::size_t>(stencils) * static_cast<std::size_t>(v.points), scalar, left());
    for (int n : t.rates_) {
      for (int kind = 0; kind < 2; ++kind) {
        const std::size_t count = half_count(kind == 0 ? n + 1 : n);
        if (count > left() / 4) r.fail("truncated index block");
        std::vector<std::uint32_t> index(count);
        for (auto& x : index) {
          x = r.get<std::uint32_t>();
          if (x >= stencils) r.fail("stencil index out of range");
        }
        (kind == 0 ? v.nodes : v.centres).push_back(std::move(index));
      }
    }
    t.valences_.push_back(std::move(v));
  }
  if (r.position() != bytes.size() - 8) r.fail("unexpected trailing bytes");
  t.index_rates();
  return t;
}

const SurfaceTables::VertexRule* SurfaceTables::vertex_rule(int valence) const {
  for (const auto& rule : rules_)
    if (rule.valence == valence) return &rule;
  return nullptr;
}

const SurfaceTables::VertexRule* SurfaceTables::polygon_vertex_rule(int valence) const {
  for (const auto& rule : polygon_rules_)
    if (rule.valence == valence) return &rule;
  return nullptr;
}

std::vector<int> SurfaceTables::valences() const {
  std::vector<int> out;
  for (const auto& v : valences_) out.push_back(v.valence);
  return out;
}

bool SurfaceTables::has_valence(int v) const {
  if (v == 4) return true;
  for (const auto& x : valences_)
    if (x.valence == v) return true;
  return false;
}

void SurfaceTables::index_rates() {
  slot_of_rate_.clear();
  for (std::size_t k = 0; k < rates_.size(); ++k) {
    const auto n = static_cast<std::size_t>(rates_[k]);
    if (slot_of_rate_.size() <= n) slot_of_rate_.resize(n + 1, -1);
    slot_of_rate_[n] = static_cast<int>(k);
  }
}

int SurfaceTables::checked_slot(int n) const {
  const int slot = rate_slot(n);
  if (slot < 0) throw std::out_of_range("rate " + std::to_string(n) + " is not in the surface table");
  return slot;
}

const double* SurfaceTables::stored_weights(const Valence& v, int slot, long i, long j, bool centre) const {
  const auto& index = centre ? v.centres[static_cast<std::size_t>(slot)] : v.nodes[static_cast<std::size_t>(slot)];
  return v.weights.data() +
         static_cast<std::size_t>(index[static_cast<std::size_t>(j * (j + 1) / 2 + i)]) * static_cast<std::size_t>(v.points);
}

int SurfaceTables::rate_slot(int n) const {
  return n >= 0 && static_cast<std::size_t>(n) < slot_of_rate_.size() ? slot_of_rate_[static_cast<std::size_t>(n)] : -1;
}

const SurfaceTables::Valence& SurfaceTables::valence_data(int v) const {
  for (const auto& x : valences_)
    if (x.valence == v) return x;
  throw std::out_of_range("valence " + std::to_string(v) + " is not in the surface table");
}

void SurfaceTables::node_stencil(int valence, int n, int i, int j, double* weights) const {
  const int slot = checked_slot(n);
  if (i < 0 || j < 0 || i > n || j > n) throw std::out_of_range("node index outside 0..n");
  stencil(valence, slot, 2L * i, 2L * j, false, weights);
}

void SurfaceTables::centre_stencil(int valence, int n, int i, int j, double* weights) const {
  const int slot = checked_slot(n);
  if (i < 0 || j < 0 || i >= n || j >= n) throw std::out_of_range("cell index outside 0..n-1");
  stencil(valence, slot, 2L * i + 1, 2L * j + 1, true, weights);
}

const double* SurfaceTables::centre_weights(int valence, int n, int i, int j, bool& mirrored) const {
  const int slot = checked_slot(n);
  mirrored = i > j;
  return stored_weights(valence_data(valence), slot, mirrored ? j : i, mirrored ? i : j, true);
}

void SurfaceTables::regular_weights_at(int slot, long a, double* w4) const {
  const auto& phi = regular_[static_cast<std::size_t>(slot)];
  const std::int64_t first = regular_first_[static_cast<std::size_t>(slot)];
  for (int p = -1; p <= 2; ++p) {
    const std::int64_t idx = a - 2L * rates_[static_cast<std::size_t>(slot)] * p - first;
    w4[p + 1] = idx >= 0 && idx < static_cast<std::int64_t>(phi.size()) ? phi[static_cast<std::size_t>(idx)] : 0.0;
  }
}

void SurfaceTables::regular_weights(int n, long a, double* w4) const {
  const int slot = checked_slot(n);
  regular_weights_at(slot, a, w4);
}

void SurfaceTables::stencil(int valence, int slot, long a, long b, bool centre, double* weights) const {
  if (valence == 4) {  // regular: phi(x - p) phi(y - q), points row by row
    double wx[4], wy[4];
    regular_weights_at(slot, a, wx);
    regular_weights_at(slot, b, wy);
    for (int q = 0; q < 4; ++q)
      for (int p = 0; p < 4; ++p) weights[q * 4 + p] = wx[p] * wy[q];
    return;
  }
  const Valence& v = valence_data(valence);
  const bool mirrored = a > b;
  const long lo = mirrored ? b : a, hi = mirrored ? a : b;
  const double* w = centre ? stored_weights(v, slot, (lo - 1) / 2, (hi - 1) / 2, true) : stored_weights(v, slot, lo / 2, hi / 2, false);
  for (int h = 0; h < v.points; ++h) weights[mirrored ? v.reflection[static_cast<std::size_t>(h)] : h] = w[h];
}

}  // namespace stencil_runtime
