#pragma once
#include <string>
#include <vector>

namespace sg {

// "24" -> 1..24, "12-24" -> 12..24, "3,5,7" -> {3,5,7}; mixed lists like "1-4,8" too.
// Sorted, without duplicates. Throws sg::Error on anything else or a rate < 1.
std::vector<long> parse_rate_spec(const std::string& spec, const std::string& what = "--n");

// The same grammar for --valence, except that a single number means that one
// valence, not 1..N. Throws sg::Error for a valence below 3.
std::vector<int> parse_valence_spec(const std::string& spec);

}  // namespace sg
