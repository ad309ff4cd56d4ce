#include "convergence_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace stencil_tools {

namespace {

std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else out += c;
  }
  return out;
}

std::string format(const char* pattern, double a, double b = 0, double c = 0, double d = 0) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, pattern, a, b, c, d);
  return buffer;
}

}  // namespace

std::string convergence_svg(const std::vector<stencil_runtime::FitIteration>& history, const std::string& title) {
  constexpr double kWidth = 640, kHeight = 400, kLeft = 70, kRight = 20, kTop = 40, kBottom = 50;
  constexpr double kFloor = 1e-16;  // errors below this are drawn at it (log scale)
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& it : history)
    for (const double e : {it.rms, it.max}) {
      const double l = std::log10(std::max(e, kFloor));
      lo = std::min(lo, l), hi = std::max(hi, l);
    }
  if (history.empty()) lo = -1, hi = 0;
  lo = std::floor(lo), hi = std::ceil(hi);
  if (hi <= lo) hi = lo + 1;
  const double last = history.empty() ? 1 : std::max(1, history.back().iteration);
  const auto x_of = [&](double i) { return kLeft + (kWidth - kLeft - kRight) * i / last; };
  const auto y_of = [&](double e) {
    return kTop + (kHeight - kTop - kBottom) * (hi - std::log10(std::max(e, kFloor))) / (hi - lo);
  };
  std::string svg = format("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%g\" height=\"%g\" font-family=\"sans-serif\" "
                           "font-size=\"12\">\n<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n",
                           kWidth, kHeight);
  svg += format("<text x=\"%g\" y=\"22\" font-size=\"14\">", kLeft) + escaped(title) + "</text>\n";
  // Axes, decades and iteration ticks.
  svg += format("<path d=\"M%g %gV%gH%g\" stroke=\"black\" fill=\"none\"/>\n", kLeft, kTop, kHeight - kBottom, kWidth - kRight);
  for (double d = lo; d <= hi; ++d) {
    const double y = y_of(std::pow(10.0, d));
    svg += format("<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke=\"#ddd\"/>", kLeft, y, kWidth - kRight, y);
    svg += format("<text x=\"%g\" y=\"%g\" text-anchor=\"end\">1e%g</text>\n", kLeft - 6, y + 4, d);
  }
  const int step = std::max(1, static_cast<int>(std::ceil(last / 10)));
  for (int i = 0; i <= last; i += step)
    svg += format("<text x=\"%g\" y=\"%g\" text-anchor=\"middle\">%g</text>\n", x_of(i), kHeight - kBottom + 18, i);
  svg += format("<text x=\"%g\" y=\"%g\" text-anchor=\"middle\">iteration</text>\n", (kLeft + kWidth - kRight) / 2,
                kHeight - 12);
  svg += format("<text transform=\"translate(16 %g) rotate(-90)\" text-anchor=\"middle\">error / diagonal</text>\n",
                (kTop + kHeight - kBottom) / 2);
  // The two series.
  const auto series = [&](bool max, const char* colour, const char* name, double legend_y) {
    std::string points;
    for (const auto& it : history) points += format("%.2f,%.2f ", x_of(it.iteration), y_of(max ? it.max : it.rms));
    svg += std::string("<polyline fill=\"none\" stroke=\"") + colour + "\" stroke-width=\"2\" points=\"" + points + "\"/>\n";
    svg += format("<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke-width=\"2\" ", kWidth - 130, legend_y,
                  kWidth - 105, legend_y) +
           "stroke=\"" + colour + "\"/>";
    svg += format("<text x=\"%g\" y=\"%g\">", kWidth - 98, legend_y + 4) + name + "</text>\n";
  };
  series(true, "#c0392b", "max error", kTop + 10);
  series(false, "#2471a3", "RMS error", kTop + 28);
  return svg + "</svg>\n";
}

}  // namespace stencil_tools
