#include "stencil_runtime/error.hpp"
#include "rate_choice.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "mesh/polygon_links.hpp"
#include "stencil_runtime/limits.hpp"
#include "tool_support.hpp"

namespace stencil_tools {

using stencil_runtime::Mesh;
namespace limits = stencil_runtime::limits;

std::vector<int> rates_from_file(const std::string& path, std::size_t faces) {
  std::istringstream in(read_text_file(path));
  std::vector<int> rates;
  std::string line;
  long number = 0;
  while (std::getline(in, line)) {
    ++number;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream ls(line);
    std::string word, extra;
    if (!(ls >> word)) continue;
    if (ls >> extra) throw std::runtime_error(path + ":" + std::to_string(number) + ": one rate per line, got " + stencil_runtime::quoted_excerpt(line));
    std::size_t r = 0;
    try {
      r = parse_index(word, "rate");
    } catch (const std::exception&) {
      throw std::runtime_error(path + ":" + std::to_string(number) + ": " + stencil_runtime::quoted_excerpt(word) + " is not a rate 1.." +
                               std::to_string(limits::kMaxRate));
    }
    if (r < 1 || r > static_cast<std::size_t>(limits::kMaxRate))
      throw std::runtime_error(path + ":" + std::to_string(number) + ": rate must be 1.." + std::to_string(limits::kMaxRate));
    rates.push_back(static_cast<int>(r));
  }
  if (rates.size() != faces)
    throw std::runtime_error(path + ": " + std::to_string(rates.size()) + " rates for a mesh of " +
                             std::to_string(faces) + " faces (one per line, in face order)");
  return rates;
}

namespace {

using V = std::array<double, 3>;
V sub(const V& a, const V& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double norm(const V& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

// The smallest rate n with `need` <= n^2 (rounding up), within 1..kMaxRate:
// computed in double, so tiny tolerances cannot overflow an integer.
int rate_for(double need) {
  if (!(need > 1)) return 1;
  const double n = std::ceil(std::sqrt(need));
  return n >= limits::kMaxRate ? limits::kMaxRate : static_cast<int>(n);
}

}  // namespace

std::vector<int> rates_for_tolerance(const Mesh& mesh, double tolerance) {
  if (!(tolerance > 0) || !std::isfinite(tolerance)) throw std::runtime_error("--tolerance must be a positive finite number");
  const stencil_runtime::Connectivity connectivity{mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices};
  const stencil_runtime::PolygonLinks links = stencil_runtime::link_polygons(connectivity);
  auto at = [&](std::size_t h) -> const V& { return mesh.positions[static_cast<std::size_t>(mesh.face_vertices[h])]; };
  auto prev = [&](std::size_t h) {
    const std::size_t f = links.face_of[h];
    return h == links.start[f] ? links.start[f + 1] - 1 : h - 1;
  };
  std::vector<int> rates(mesh.face_count());
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    double d = 0;
    const std::size_t first = links.start[f], k = links.start[f + 1] - first;
    for (std::size_t h = first; h < links.start[f + 1]; ++h) {
      // The outgoing half-edge half the valence round from h, counter-clockwise.
      const int valence = links.valence[static_cast<std::size_t>(mesh.face_vertices[h])];
      std::size_t e = h;
      for (int t = 0; t < valence / 2; ++t) e = links.twin[prev(e)];
      d = std::max(d, norm(sub(sub(at(links.next[h]), at(h)), sub(at(h), at(links.next[e])))));
      if (k == 4) {
        const std::size_t c1 = links.next[h], c2 = links.next[c1], c3 = links.next[c2];
        d = std::max(d, norm(sub(sub(at(c2), at(c1)), sub(at(c3), at(h)))));
      }
    }
    rates[f] = rate_for(d / (8 * tolerance));
  }
  return rates;
}

Camera parse_camera(const std::string& text) {
  std::array<double, 6> v{};
  std::istringstream in(text);
  char comma = 0;
  for (int k = 0; k < 6; ++k) {
    if (!(in >> v[static_cast<std::size_t>(k)]) || !std::isfinite(v[static_cast<std::size_t>(k)]) ||
        (k < 5 && !(in >> comma && comma == ',')))
      throw std::runtime_error("--camera expects EX,EY,EZ,TX,TY,TZ (eye and target, finite numbers), got " + stencil_runtime::quoted_excerpt(text));
  }
  if (in >> comma) throw std::runtime_error("--camera expects six numbers, got " + stencil_runtime::quoted_excerpt(text));
  Camera c;
  c.eye = {v[0], v[1], v[2]};
  c.target = {v[3], v[4], v[5]};
  return c;
}

std::vector<int> rates_for_view(const Mesh& mesh, const Camera& cam, double target_pixels) {
  if (!(target_pixels > 0) || !std::isfinite(target_pixels)) throw std::runtime_error("--pixels must be a positive finite number");
  if (!(cam.fov_degrees > 0 && cam.fov_degrees < 180)) throw std::runtime_error("--fov must be between 0 and 180 degrees");
  if (cam.width_pixels < 1 || cam.width_pixels > 1000000) throw std::runtime_error("--width must be 1..1000000 pixels");
  const V forward0 = sub(cam.target, cam.eye);
  const double fl = norm(forward0);
  if (!std::isfinite(fl))
    throw std::runtime_error("--camera: the coordinates are too large (the distance from eye to target overflows)");
  if (!(fl > 0)) throw std::runtime_error("--camera: eye and target coincide");
  const V fwd{forward0[0] / fl, forward0[1] / fl, forward0[2] / fl};
  const double focal = 0.5 * cam.width_pixels / std::tan(0.5 * cam.fov_degrees * M_PI / 180);
  // Pixel length of a short segment at distance depth: focal * length / depth
  // (a conservative, rotation-free projection of each edge).
  std::vector<int> rates(mesh.face_count());
  std::size_t offset = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const int k = mesh.face_sizes[f];
    double longest = 0;
    bool visible = false;
    for (int c = 0; c < k; ++c) {
      const auto& p = mesh.positions[static_cast<std::size_t>(mesh.face_vertices[offset + static_cast<std::size_t>(c)])];
      const auto& q = mesh.positions[static_cast<std::size_t>(mesh.face_vertices[offset + static_cast<std::size_t>((c + 1) % k)])];
      const V mid{(p[0] + q[0]) / 2 - cam.eye[0], (p[1] + q[1]) / 2 - cam.eye[1], (p[2] + q[2]) / 2 - cam.eye[2]};
      const double depth = mid[0] * fwd[0] + mid[1] * fwd[1] + mid[2] * fwd[2];
      if (depth <= 1e-9) continue;
      visible = true;
      longest = std::max(longest, focal * norm(sub(p, q)) / depth);
    }
    const double need = longest / target_pixels;
    rates[f] = visible ? rate_for(need * need) : 1;
    offset += static_cast<std::size_t>(k);
  }
  return rates;
}

}  // namespace stencil_tools
