#include "curve/plot_svg.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace sg {

std::string plot_table_svg(const CurveTable& t) {
  const double W = 800, H = 420, margin = 50;
  double xmin = 0, xmax = 0, ymin = 0, ymax = 1;
  struct Line { std::string name; std::vector<std::pair<double, double>> pts; };
  std::vector<Line> lines;
  for (const auto& f : t.functions) {
    // Each non-uniform type is drawn as the basis of the control point it is placed at.
    const double offset = f.placement == Placement::Everywhere ? 0.0 : static_cast<double>(f.position);
    Line line{f.name, {}};
    const double lo = to_double(f.support_lo) + offset, hi = to_double(f.support_hi) + offset;
    line.pts.emplace_back(lo, 0.0);
    for (const auto& [k, v] : f.values) line.pts.emplace_back(static_cast<double>(k) / static_cast<double>(t.n) + offset, to_double(v));
    line.pts.emplace_back(hi, 0.0);
    std::sort(line.pts.begin(), line.pts.end());
    for (const auto& [x, y] : line.pts) {
      xmin = std::min(xmin, x);
      xmax = std::max(xmax, x);
      ymin = std::min(ymin, y);
      ymax = std::max(ymax, y);
    }
    lines.push_back(std::move(line));
  }
  if (xmax - xmin < 1e-9) xmax = xmin + 1;
  const double pad = 0.05 * (ymax - ymin);
  ymin -= pad;
  ymax += pad;
  auto X = [&](double x) { return margin + (x - xmin) / (xmax - xmin) * (W - 2 * margin); };
  auto Y = [&](double y) { return H - margin - (y - ymin) / (ymax - ymin) * (H - 2 * margin); };
  static const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
  std::ostringstream s;
  char buf[256];
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H << "\" viewBox=\"0 0 " << W << ' ' << H
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  std::snprintf(buf, sizeof buf, "<text x=\"%g\" y=\"20\" font-size=\"15\">%s, n = %ld (exact values on the grid (1/n)Z)</text>\n", margin, t.scheme.c_str(), t.n);
  s << buf;
  // Axes: y = 0 and y = 1, and integer ticks on x.
  for (double y : {0.0, 1.0}) {
    std::snprintf(buf, sizeof buf, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#999\" stroke-dasharray=\"%s\"/>\n<text x=\"10\" y=\"%.2f\">%g</text>\n",
                  X(xmin), Y(y), X(xmax), Y(y), y == 0 ? "none" : "4 3", Y(y) + 4, y);
    s << buf;
  }
  for (long i = static_cast<long>(xmin); i <= static_cast<long>(xmax); ++i) {
    std::snprintf(buf, sizeof buf, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#999\"/>\n<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\">%ld</text>\n",
                  X(i), Y(0) - 4, X(i), Y(0) + 4, X(i), H - margin + 20, i);
    s << buf;
  }
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const char* c = colours[i % 8];
    s << "<polyline fill=\"none\" stroke=\"" << c << "\" stroke-width=\"1.6\" points=\"";
    for (const auto& [x, y] : lines[i].pts) {
      std::snprintf(buf, sizeof buf, "%.2f,%.2f ", X(x), Y(y));
      s << buf;
    }
    s << "\"/>\n";
    for (const auto& [x, y] : lines[i].pts) {
      std::snprintf(buf, sizeof buf, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"1.8\" fill=\"%s\"/>\n", X(x), Y(y), c);
      s << buf;
    }
    std::snprintf(buf, sizeof buf, "<text x=\"%.2f\" y=\"%.2f\" fill=\"%s\">%s</text>\n", W - margin - 90, 40.0 + 16.0 * static_cast<double>(i), c, lines[i].name.c_str());
    s << buf;
  }
  s << "</svg>\n";
  return s.str();
}

}  // namespace sg
