#pragma once
// Pieces shared by the quad and the triangle surface pipelines
// (generate_quad, generate_triangle): the order in which the (valence,
// rate) jobs run, and the parallel serialisation of the per-table JSON files.
#include <algorithm>
#include <string>
#include <tbb/parallel_for.h>
#include <utility>
#include <vector>

#include "algebra/real.hpp"
#include "common/atomic_output.hpp"

namespace sg {

// Every (valence index, rate index) pair, largest first, so that the last jobs
// to finish are short.
inline std::vector<std::pair<std::size_t, std::size_t>> valence_rate_jobs(const std::vector<int>& valences,
                                                                          const std::vector<long>& rates) {
  std::vector<std::pair<std::size_t, std::size_t>> jobs;
  for (std::size_t v = 0; v < valences.size(); ++v)
    for (std::size_t r = 0; r < rates.size(); ++r) jobs.emplace_back(v, r);
  std::sort(jobs.begin(), jobs.end(), [&](auto a, auto b) {
    return rates[a.second] * (valences[a.first] + 4) > rates[b.second] * (valences[b.first] + 4);
  });
  return jobs;
}

// Adds v<V>/n<N>.json for every table (tables[valence][rate]); serialising the
// exact numbers is a good part of the work, so it runs in parallel.
template <class Table, class ToJson>
void add_table_files(OutputTransaction& tx, const std::vector<std::vector<Table>>& tables, ToJson to_json) {
  std::vector<const Table*> all;
  for (const auto& by_rate : tables)
    for (const Table& t : by_rate) all.push_back(&t);
  std::vector<std::string> texts(all.size());
  sg::prepare_real_limits();  // before threads first use Real (algebra/real.hpp)
  tbb::parallel_for(std::size_t(0), all.size(), [&](std::size_t k) { texts[k] = to_json(*all[k]); });
  for (std::size_t k = 0; k < all.size(); ++k)
    tx.add("v" + std::to_string(all[k]->valence) + "/n" + std::to_string(all[k]->n) + ".json", std::move(texts[k]));
}

}  // namespace sg
