#include <algorithm>

#include "family.hpp"

namespace stencil_runtime {

std::string compact_list(const std::vector<int>& sorted, bool always_range) {
  std::string out;
  for (std::size_t k = 0; k < sorted.size();) {
    std::size_t end = k;
    while (end + 1 < sorted.size() && sorted[end + 1] == sorted[end] + 1) ++end;
    if (!out.empty()) out += ",";
    out += std::to_string(sorted[k]);
    if (end > k) out += "-" + std::to_string(sorted[end]);
    k = end + 1;
  }
  // stencilgen reads a lone N as 1..N, a list or range as written.
  if (always_range && sorted.size() == 1) out += "-" + out;
  return out;
}

bool ValenceCheck::covered(int valence) const {
  return std::find(table_valences_.begin(), table_valences_.end(), valence) != table_valences_.end();
}

void ValenceCheck::add(int valence, const std::string& who) {
  if (valence < 3)
    throw MeshError(who + " has valence " + std::to_string(valence) +
                    "; subdivision surfaces need every vertex in at least 3 faces (this mesh folds back on itself there)");
  if (valence > limits::kMaxValence)
    throw MeshError(who + " has valence " + std::to_string(valence) + "; the runtime supports valences up to " +
                    std::to_string(limits::kMaxValence) + " (split the faces round it)");
  if (covered(valence)) return;
  if (missing_.empty()) first_missing_ = who + " has valence " + std::to_string(valence);
  if (std::find(missing_.begin(), missing_.end(), valence) == missing_.end()) missing_.push_back(valence);
}

void ValenceCheck::add_boundary(int faces, const std::string& who) {
  const int valence = std::max(faces, 3);
  if (missing_.empty()) first_missing_ = who;
  if (std::find(missing_.begin(), missing_.end(), valence) == missing_.end()) missing_.push_back(valence);
}

void ValenceCheck::finish() const {
  if (missing_.empty()) return;
  std::vector<int> missing = missing_;
  std::sort(missing.begin(), missing.end());
  std::vector<int> all = table_valences_;
  all.insert(all.end(), missing.begin(), missing.end());
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  all.erase(std::remove(all.begin(), all.end(), regular_), all.end());  // stencilgen writes the regular patch anyway
  if (all.empty()) all = missing;
  throw MeshError(first_missing_ + ", which the tables do not cover (missing valence" + (missing.size() > 1 ? "s " : " ") +
                  compact_list(missing, false) + "); generate tables that cover this mesh with: stencilgen --scheme " +
                  scheme_ + " --valence " + compact_list(all, false) + " --n " + compact_list(table_rates_, true) +
                  " --out <dir>");
}

}  // namespace stencil_runtime
