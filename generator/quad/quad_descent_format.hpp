#pragma once
// The name and version of descent.json (quad_descent_json.hpp), apart so that
// code which only recognises the format need not see the descent's types.
namespace sg {

inline constexpr const char* kQuadDescentFormat = "stencilgen-quad-descent";
inline constexpr int kQuadDescentVersion = 4;  // 2: tangent stencils at the vertex; 3: boundary sectors; 4: cone points

}  // namespace sg
