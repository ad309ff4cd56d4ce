#pragma once
// Resolved scheme parameters as a JSON object of exact rational strings, as
// tables record them and as the scheme hash covers them.
#include "algebra/expression.hpp"

namespace sg {

template <class Json>
Json parameters_json(const Bindings& parameters) {
  Json out = Json::object();
  for (const auto& [name, value] : parameters) out[name] = to_string(value);
  return out;
}

}  // namespace sg
