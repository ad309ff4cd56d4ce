#include "common/rate_spec.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>

#include "base/error.hpp"
#include "base/limits.hpp"

namespace sg {
namespace {

struct SpecReader {
  const std::string& spec;
  long max;
  const std::string& max_name;
  const std::string& what;

  [[noreturn]] void fail(const std::string& problem) const {
    throw Error(what + " '" + excerpt(spec) + "': " + problem);
  }
  long number(const std::string& text) const {
    if (text.empty() || !std::all_of(text.begin(), text.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
      fail("'" + excerpt(text) + "' is not a positive integer");
    long v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec == std::errc::result_out_of_range || v > max)  // out of range of long is above max too
      fail(excerpt(text) + " is above " + std::to_string(max) + ", " + max_name);
    if (ec != std::errc() || end != text.data() + text.size()) fail("'" + excerpt(text) + "' is not a positive integer");
    if (v < 1) fail(text + " is less than 1");
    return v;
  }
};

}  // namespace

std::vector<long> parse_rate_spec(const std::string& spec, long max, const std::string& max_name, const std::string& what) {
  const SpecReader reader{spec, max, max_name, what};
  std::vector<long> out;
  if (spec.empty()) throw Error(what + " is empty");
  const bool single = spec.find_first_of(",-") == std::string::npos;
  if (single) {  // "24" means every rate 1..24
    const long last = reader.number(spec);
    for (long v = 1; v <= last; ++v) out.push_back(v);
    return out;
  }
  std::size_t start = 0;
  while (start <= spec.size()) {
    const std::size_t comma = spec.find(',', start);
    const std::string item = spec.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const std::size_t dash = item.find('-');
    if (dash == std::string::npos) {
      out.push_back(reader.number(item));
    } else {
      const long lo = reader.number(item.substr(0, dash));
      const long hi = reader.number(item.substr(dash + 1));
      if (hi < lo) reader.fail("range " + item + " is empty");
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
  const std::string max_name = "the largest valence", what = "--valence";
  const bool single = !spec.empty() && spec.find_first_not_of("0123456789") == std::string::npos;
  const std::vector<long> values = single ? std::vector<long>{SpecReader{spec, limits::kMaxValence, max_name, what}.number(spec)}
                                          : parse_rate_spec(spec, limits::kMaxValence, max_name, what);
  std::vector<int> valences;
  for (long v : values) {
    if (v < limits::kMinValence)
      throw Error("--valence: valences start at " + std::to_string(limits::kMinValence) + ", got " + std::to_string(v));
    valences.push_back(static_cast<int>(v));
  }
  return valences;
}

void check_rates(const std::vector<long>& rates, long max, const std::string& max_name) {
  for (long n : rates)
    if (n < 1 || n > max)
      throw Error("rate n = " + std::to_string(n) + " is outside 1.." + std::to_string(max) + " (" + max_name + ")");
}

void check_valences(const std::vector<int>& valences, int lo, int hi, const std::string& source) {
  for (int v : valences)
    if (v < lo || v > hi)
      throw Error(source + ": valence " + std::to_string(v) + " is outside the range " + std::to_string(lo) + ".." +
                  std::to_string(hi) + " the scheme covers (checked for every requested valence before any work)");
}

}  // namespace sg
