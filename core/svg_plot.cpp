#include "core/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace simcap {

namespace {

constexpr const char* kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                    "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"};

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

// Tick label with as many decimals as the tick step needs.
std::string tick_label(double v, double step) {
  const int decimals = step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, std::abs(v) < 1e-12 ? 0.0 : v);
  return buf;
}

std::string text(double x, double y, const std::string& s, const char* anchor = "start",
                 const char* extra = "") {
  return "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" text-anchor=\"" + anchor + "\"" + extra +
         ">" + xml_escape(s) + "</text>\n";
}

std::string line(double x1, double y1, double x2, double y2, const char* style) {
  return "<line x1=\"" + num(x1) + "\" y1=\"" + num(y1) + "\" x2=\"" + num(x2) + "\" y2=\"" +
         num(y2) + "\" " + style + "/>\n";
}

std::string svg_open(int width, int height) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) +
         "\" height=\"" + std::to_string(height) + "\" viewBox=\"0 0 " + std::to_string(width) +
         " " + std::to_string(height) +
         "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" "
         "fill=\"white\"/>\n";
}

double finite_max(const std::vector<double>& v, double start) {
  double m = start;
  for (double x : v) {
    if (std::isfinite(x)) m = std::max(m, x);
  }
  return m;
}

}  // namespace

std::string xml_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::vector<double> nice_ticks(double lo, double hi, int target) {
  if (!(hi > lo)) hi = lo + 1.0;
  const double raw = (hi - lo) / std::max(target, 1);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * mag;
    if (step >= raw) break;
  }
  std::vector<double> ticks;
  const double first = std::floor(lo / step + 1e-9) * step;
  for (double t = first; t < hi + step - 1e-9 * step; t += step) ticks.push_back(t);
  if (ticks.size() < 2) ticks.push_back(first + step);
  return ticks;
}

std::string line_plot_svg(const LinePlot& plot) {
  const double left = 64, right = 20, top = 36, bottom = 48;
  const double w = plot.width - left - right, h = plot.height - top - bottom;
  const bool categorical = !plot.x_categories.empty();

  double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo, y_hi = 0.0;
  for (const auto& s : plot.series) {
    for (size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.y[i])) continue;
      x_lo = std::min(x_lo, s.x[i]);
      x_hi = std::max(x_hi, s.x[i]);
    }
    y_hi = finite_max(s.y, y_hi);
  }
  if (plot.reference_y) y_hi = std::max(y_hi, *plot.reference_y);
  if (categorical) {
    x_lo = -0.5;
    x_hi = static_cast<double>(plot.x_categories.size()) - 0.5;
  } else if (!std::isfinite(x_lo)) {
    x_lo = 0.0;
    x_hi = 1.0;
  } else if (x_hi <= x_lo) {
    x_lo -= 0.5;
    x_hi += 0.5;
  } else if (plot.markers) {
    // Keeps the first and last markers off the axes.
    const double pad = 0.04 * (x_hi - x_lo);
    x_lo -= pad;
    x_hi += pad;
  }
  const std::vector<double> y_ticks = nice_ticks(0.0, y_hi > 0 ? y_hi : 1.0);
  const double y_top = y_ticks.back();
  const auto px = [&](double x) { return left + (x - x_lo) / (x_hi - x_lo) * w; };
  const auto py = [&](double y) { return top + h - y / y_top * h; };

  std::string svg = svg_open(plot.width, plot.height);
  svg += text(left, 20, plot.title, "start", " font-size=\"14\" font-weight=\"bold\"");
  const double y_step = y_ticks.size() > 1 ? y_ticks[1] - y_ticks[0] : 1.0;
  for (double t : y_ticks) {
    svg += line(left, py(t), left + w, py(t), "stroke=\"#e0e0e0\"");
    svg += text(left - 6, py(t) + 4, tick_label(t, y_step), "end");
  }
  if (categorical) {
    for (size_t i = 0; i < plot.x_categories.size(); ++i) {
      const double x = px(static_cast<double>(i));
      svg += line(x, top + h, x, top + h + 4, "stroke=\"#444\"");
      svg += text(x, top + h + 16, plot.x_categories[i], "middle");
    }
  } else {
    const std::vector<double> x_ticks = nice_ticks(x_lo, x_hi, 8);
    const double x_step = x_ticks.size() > 1 ? x_ticks[1] - x_ticks[0] : 1.0;
    for (double t : x_ticks) {
      if (t < x_lo - 1e-9 || t > x_hi + 1e-9) continue;
      svg += line(px(t), top + h, px(t), top + h + 4, "stroke=\"#444\"");
      svg += text(px(t), top + h + 16, tick_label(t, x_step), "middle");
    }
  }
  svg += line(left, top + h, left + w, top + h, "stroke=\"#444\"");
  svg += line(left, top, left, top + h, "stroke=\"#444\"");
  svg += text(left + w / 2, plot.height - 8, plot.x_label, "middle");
  svg += text(14, top + h / 2, plot.y_label, "middle",
              (" transform=\"rotate(-90 14 " + num(top + h / 2) + ")\"").c_str());
  if (plot.reference_y) {
    svg += line(left, py(*plot.reference_y), left + w, py(*plot.reference_y),
                "stroke=\"#999\" stroke-dasharray=\"6 4\"");
    svg +=
        text(left + 4, py(*plot.reference_y) - 4, plot.reference_label, "start", " fill=\"#666\"");
  }
  for (size_t k = 0; k < plot.series.size(); ++k) {
    const PlotSeries& s = plot.series[k];
    const char* colour = kPalette[k % std::size(kPalette)];
    std::string points;
    const auto flush = [&] {
      if (!points.empty()) {
        svg += "<polyline fill=\"none\" stroke=\"" + std::string(colour) +
               "\" stroke-width=\"1.5\" points=\"" + points + "\"/>\n";
      }
      points.clear();
    };
    for (size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.y[i])) {
        flush();
        continue;
      }
      points += (points.empty() ? "" : " ") + num(px(s.x[i])) + "," + num(py(s.y[i]));
      if (plot.markers) {
        svg += "<circle cx=\"" + num(px(s.x[i])) + "\" cy=\"" + num(py(s.y[i])) +
               "\" r=\"3\" fill=\"" + colour + "\"/>\n";
      }
    }
    flush();
    const double ly = top + 4 + 16.0 * static_cast<double>(k);
    svg += line(left + w - 150, ly, left + w - 130, ly,
                ("stroke=\"" + std::string(colour) + "\" stroke-width=\"2\"").c_str());
    svg += text(left + w - 124, ly + 4, s.name);
  }
  svg += "</svg>\n";
  return svg;
}

std::string bar_chart_svg(const BarChart& chart) {
  const double label_w = 130, top = 36, value_w = 150;
  const double w = chart.width - label_w - value_w - 10;
  const int height = static_cast<int>(top + chart.bar_height * chart.labels.size() + 40);
  const std::vector<double> ticks = nice_ticks(0.0, std::max(finite_max(chart.values, 0.0), 1e-9));
  const double x_top = ticks.back();
  const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : 1.0;
  const auto px = [&](double v) { return label_w + v / x_top * w; };
  const double bottom = top + chart.bar_height * static_cast<double>(chart.labels.size());

  std::string svg = svg_open(chart.width, height);
  svg += text(8, 20, chart.title, "start", " font-size=\"14\" font-weight=\"bold\"");
  for (double t : ticks) {
    svg += line(px(t), top, px(t), bottom, "stroke=\"#e0e0e0\"");
    svg += text(px(t), bottom + 14, tick_label(t, step), "middle");
  }
  svg += text(label_w + w / 2, bottom + 32, chart.value_label, "middle");
  for (size_t i = 0; i < chart.labels.size(); ++i) {
    const double y = top + chart.bar_height * static_cast<double>(i);
    svg += text(label_w - 6, y + chart.bar_height * 0.7, chart.labels[i], "end");
    const double v = i < chart.values.size() ? chart.values[i] : std::nan("");
    std::string value = "n/a";
    if (std::isfinite(v)) {
      svg += "<rect x=\"" + num(label_w) + "\" y=\"" + num(y + 2) + "\" width=\"" +
             num(px(v) - label_w) + "\" height=\"" + num(chart.bar_height - 4.0) + "\" fill=\"" +
             kPalette[0] + "\"/>\n";
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.1f", v);
      value = buf;
    }
    if (i < chart.annotations.size() && !chart.annotations[i].empty()) {
      value += "  " + chart.annotations[i];
    }
    svg += text((std::isfinite(v) ? px(v) : label_w) + 4, y + chart.bar_height * 0.7, value);
  }
  svg += line(label_w, top, label_w, bottom, "stroke=\"#444\"");
  svg += "</svg>\n";
  return svg;
}

}  // namespace simcap
