#pragma once
#include <string>
#include <vector>

namespace sg {

// "24" -> 1..24, "12-24" -> 12..24, "3,5,7" -> {3,5,7}; mixed lists like "1-4,8" too.
// Sorted, without duplicates. Throws sg::Error, naming `what` (the option) and
// the spec, on anything else, a rate < 1, or a rate above `max`; `max_name`
// says which limit that is ("the largest rate for curve schemes"). Numbers of
// any length are read without overflow.
std::vector<long> parse_rate_spec(const std::string& spec, long max, const std::string& max_name,
                                  const std::string& what = "--n");

// Throws sg::Error unless every rate lies in 1..max (for callers that take
// rates from elsewhere than a spec).
void check_rates(const std::vector<long>& rates, long max, const std::string& max_name);

// The same grammar for --valence, except that a single number means that one
// valence, not 1..N; every valence must lie in limits::kMinValence..kMaxValence.
std::vector<int> parse_valence_spec(const std::string& spec);

// Throws sg::Error unless every valence lies in the range [lo, hi] a scheme
// covers (`source` names the scheme), before any of them is worked on.
void check_valences(const std::vector<int>& valences, int lo, int hi, const std::string& source);

}  // namespace sg
