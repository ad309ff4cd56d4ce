#include "common/rate_spec.hpp"

#include <algorithm>
#include <cctype>

#include "base/error.hpp"

namespace sg {
namespace {
long parse_positive(const std::string& text, const std::string& spec, const std::string& what) {
  if (text.empty() || text.size() > 6 || !std::all_of(text.begin(), text.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
    throw Error(what + " '" + spec + "': '" + text + "' is not a positive integer (at most 6 digits)");
  const long v = std::stol(text);
  if (v < 1) throw Error(what + " '" + spec + "': " + text + " is less than 1");
  return v;
}
}  // namespace

std::vector<long> parse_rate_spec(const std::string& spec, const std::string& what) {
  std::vector<long> out;
  if (spec.empty()) throw Error(what + " is empty");
  const bool single = spec.find_first_of(",-") == std::string::npos;
  if (single) {  // "24" means every rate 1..24
    const long last = parse_positive(spec, spec, what);
    for (long v = 1; v <= last; ++v) out.push_back(v);
    return out;
  }
  std::size_t start = 0;
  while (start <= spec.size()) {
    const std::size_t comma = spec.find(',', start);
    const std::string item = spec.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const std::size_t dash = item.find('-');
    if (dash == std::string::npos) {
      out.push_back(parse_positive(item, spec, what));
    } else {
      const long lo = parse_positive(item.substr(0, dash), spec, what);
      const long hi = parse_positive(item.substr(dash + 1), spec, what);
      if (hi < lo) throw Error(what + " '" + spec + "': range " + item + " is empty");
      for (long v = lo; v <= hi; ++v) out.push_back(v);
    }
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<int> parse_valence_spec(const std::string& spec) {
  const bool single = !spec.empty() && spec.find_first_not_of("0123456789") == std::string::npos;
  std::vector<int> valences;
  for (long v : parse_rate_spec(single ? spec + "," + spec : spec, "--valence")) {
    if (v < 3) throw Error("--valence: valences start at 3, got " + std::to_string(v));
    valences.push_back(static_cast<int>(v));
  }
  return valences;
}

}  // namespace sg
