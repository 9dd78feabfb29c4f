// Small, dependency-free SVG charts for the HTML reports: line plots (error per frame, MPJPE
// against a swept parameter) and horizontal bar charts (error per joint, error by visibility).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace simcap {

struct PlotSeries {
  std::string name;
  std::vector<double> x, y;  // same length; a NaN y breaks the line
};

struct LinePlot {
  std::string title, x_label, y_label;
  std::vector<PlotSeries> series;
  // When not empty, x values are indices into these labels and the x axis is categorical.
  std::vector<std::string> x_categories;
  std::optional<double> reference_y;  // dashed horizontal line (e.g. a failure threshold)
  std::string reference_label;
  bool markers = false;  // draw a dot at every point
  int width = 760, height = 320;
};

struct BarChart {
  std::string title, value_label;
  std::vector<std::string> labels;
  std::vector<double> values;            // NaN: no bar (e.g. an empty group)
  std::vector<std::string> annotations;  // optional text after each bar (e.g. a count)
  int width = 760;
  int bar_height = 18;
};

// Complete <svg> elements, usable inline in HTML or as .svg files.
std::string line_plot_svg(const LinePlot& plot);
std::string bar_chart_svg(const BarChart& chart);

// Escapes &, <, >, " and ' for XML/HTML text and attributes.
std::string xml_escape(const std::string& text);

// "Nice" axis ticks (1, 2, 5 x 10^k steps) covering [lo, hi], about `target` of them.
std::vector<double> nice_ticks(double lo, double hi, int target = 5);

}  // namespace simcap
