#include "validate/sweep.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>

#include "core/atomic_file.h"
#include "core/csv.h"
#include "core/error.h"
#include "core/progress.h"
#include "validate/svg_plot.h"

namespace simcap {
namespace fs = std::filesystem;

namespace {

// simcap's CSV has no quoting: a comma inside a label or message would shift the columns.
std::string csv_cell(std::string s) {
  for (char& c : s) {
    if (c == ',' || c == '\n' || c == '\r') c = ';';
  }
  return s;
}

std::string fixed(double v, int decimals) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

double pck_at(const Evaluation& ev, double threshold) {
  for (const auto& p : ev.pck) {
    if (p.threshold_mm == threshold) return p.fraction;
  }
  return std::nan("");
}

std::string relative_report(const SweepOutcome& o, const fs::path& out) {
  return o.report.empty() ? "" : o.report.lexically_relative(out).generic_string();
}

void write_csv(const SweepSpec& spec, const std::vector<SweepPoint>& points,
               const std::vector<SweepOutcome>& outcomes, const fs::path& out) {
  std::vector<std::string> columns = {"point"};
  for (const auto& a : spec.axes) columns.push_back(csv_cell(a.name));
  for (const char* c :
       {"status", "frames", "mpjpe_mm", "pa_mpjpe_mm", "pck_50mm", "pck_100mm", "pck_150mm",
        "rmse_mean_mm", "wrists_elbows_mm", "failed_fraction", "report"}) {
    columns.push_back(c);
  }
  CsvWriter csv(out / "table.csv", columns);
  CsvWriter times(out / "timings.csv", {"point", "render_s", "track_s", "validate_s"});
  for (size_t i = 0; i < outcomes.size(); ++i) {
    const SweepOutcome& o = outcomes[i];
    csv.out() << i;
    for (const auto& l : points[i].labels) csv.out() << ',' << csv_cell(l);
    if (o.evaluation) {
      const Evaluation& ev = *o.evaluation;
      csv.out() << ",ok," << ev.frames.size() << ',' << fixed(ev.mpjpe_mm, 2) << ','
                << fixed(ev.pa_mpjpe_mm, 2) << ',' << fixed(pck_at(ev, 50), 4) << ','
                << fixed(pck_at(ev, 100), 4) << ',' << fixed(pck_at(ev, 150), 4) << ','
                << fixed(ev.rmse_mean_mm, 2) << ',' << fixed(ev.wrists_elbows_mm, 2) << ','
                << fixed(ev.failures.failed_fraction, 4);
    } else {
      csv.out() << ",error: " << csv_cell(o.error) << ",,,,,,,,,";
    }
    csv.out() << ',' << relative_report(o, out) << '\n';
    times.out() << i << ',' << fixed(o.render_s, 2) << ',' << fixed(o.track_s, 2) << ','
                << fixed(o.validate_s, 2) << '\n';
  }
  csv.commit();
  times.commit();
}

std::string plot_svg(const SweepSpec& spec, const std::vector<SweepPoint>& points,
                     const std::vector<SweepOutcome>& outcomes) {
  const SweepAxis& axis = spec.axes.front();
  LinePlot plot;
  plot.title = "MPJPE against " + axis.name;
  plot.x_label = axis.name;
  plot.y_label = "mm";
  plot.markers = true;
  const bool numeric = axis.numeric();
  if (!numeric) plot.x_categories = axis.labels;
  // One series per combination of the other axes' labels, in order of first appearance.
  std::map<std::vector<std::string>, size_t> series_of;
  const auto x_of = [&](const std::string& label) {
    const size_t k = std::find(axis.labels.begin(), axis.labels.end(), label) - axis.labels.begin();
    return numeric ? std::stod(label) : static_cast<double>(k);
  };
  for (size_t i = 0; i < outcomes.size(); ++i) {
    const std::vector<std::string> rest(points[i].labels.begin() + 1, points[i].labels.end());
    auto [it, added] = series_of.emplace(rest, plot.series.size());
    if (added) {
      std::string name = "MPJPE";
      for (size_t a = 1; a < spec.axes.size(); ++a) {
        name += (a == 1 ? " (" : ", ") + spec.axes[a].name + " " + rest[a - 1];
      }
      plot.series.push_back({spec.axes.size() > 1 ? name + ")" : name, {}, {}});
      if (spec.axes.size() == 1) plot.series.push_back({"PA-MPJPE", {}, {}});
    }
    const double x = x_of(points[i].labels.front());
    const auto& ev = outcomes[i].evaluation;
    plot.series[it->second].x.push_back(x);
    plot.series[it->second].y.push_back(ev ? ev->mpjpe_mm : std::nan(""));
    if (spec.axes.size() == 1) {
      plot.series[it->second + 1].x.push_back(x);
      plot.series[it->second + 1].y.push_back(ev ? ev->pa_mpjpe_mm : std::nan(""));
    }
  }
  return line_plot_svg(plot);
}

std::string html_table(const SweepSpec& spec, const std::vector<SweepPoint>& points,
                       const std::vector<SweepOutcome>& outcomes, const fs::path& out) {
  std::string s = "<table>\n<tr><th>#</th>";
  for (const auto& a : spec.axes) s += "<th>" + xml_escape(a.name) + "</th>";
  s += "<th>MPJPE mm</th><th>PA-MPJPE mm</th><th>PCK@50</th><th>PCK@100</th><th>PCK@150</th>"
       "<th>RMSE mm</th><th>wrists+elbows mm</th><th>failed frames</th><th>report</th></tr>\n";
  for (size_t i = 0; i < outcomes.size(); ++i) {
    const SweepOutcome& o = outcomes[i];
    s += "<tr><td>" + std::to_string(i) + "</td>";
    for (const auto& l : points[i].labels) s += "<td>" + xml_escape(l) + "</td>";
    if (o.evaluation) {
      const Evaluation& ev = *o.evaluation;
      for (const std::string& v :
           {fixed(ev.mpjpe_mm, 1), fixed(ev.pa_mpjpe_mm, 1), fixed(100 * pck_at(ev, 50), 1) + "%",
            fixed(100 * pck_at(ev, 100), 1) + "%", fixed(100 * pck_at(ev, 150), 1) + "%",
            fixed(ev.rmse_mean_mm, 1), fixed(ev.wrists_elbows_mm, 1),
            fixed(100 * ev.failures.failed_fraction, 1) + "%"}) {
        s += "<td>" + v + "</td>";
      }
    } else {
      s += "<td colspan=\"8\">failed: " + xml_escape(o.error) + "</td>";
    }
    const std::string link = relative_report(o, out);
    s += "<td>" + (link.empty() ? "" : "<a href=\"" + xml_escape(link) + "\">report</a>") +
         "</td></tr>\n";
  }
  return s + "</table>\n";
}

std::string config_text(const LoopConfig& c) {
  std::string s = "scene " + c.scene.string();
  s += c.frames > 0 ? ", " + std::to_string(c.frames) + " frames" : ", all frames";
  if (c.seed) s += ", seed " + std::to_string(*c.seed);
  if (!c.motion.empty()) s += ", motion " + c.motion.string();
  for (const auto& o : c.scene_overrides) s += ", " + o;
  for (const auto& [k, v] : c.track_options) s += ", track " + k + "=" + v;
  return s;
}

}  // namespace

std::string sweep_point_folder(size_t index, const SweepPoint& point) {
  char num[16];
  std::snprintf(num, sizeof num, "%02zu", index);
  std::string name = num;
  for (const auto& l : point.labels) {
    name += '_';
    for (char c : l) {
      const bool ok = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-';
      name += ok ? c : '_';
    }
  }
  return name;
}

void write_sweep_tables(const SweepSpec& spec, const std::vector<SweepPoint>& points,
                        const std::vector<SweepOutcome>& outcomes, const fs::path& out) {
  write_csv(spec, points, outcomes, out);
  const std::string svg = plot_svg(spec, points, outcomes);
  write_text_atomic(out / "mpjpe.svg", svg);
  const std::string title = spec.title.empty() ? "simcap stress sweep" : spec.title;
  write_text_atomic(
      out / "table.html",
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
          xml_escape(title) +
          "</title>\n<style>body{font-family:sans-serif;max-width:1100px;margin:2em auto}"
          "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:3px 8px}"
          "</style>\n</head>\n<body>\n<h1>" +
          xml_escape(title) + "</h1>\n<p>Sweep file <code>" + xml_escape(spec.file.string()) +
          "</code>; base: " + xml_escape(config_text(spec.base)) + ".</p>\n" +
          html_table(spec, points, outcomes, out) + svg + "</body>\n</html>\n");
}

std::vector<SweepOutcome> run_sweep(const SweepSpec& spec, const fs::path& out,
                                    const SweepPointRunner& run, bool quiet) {
  const std::vector<SweepPoint> points = sweep_points(spec);
  std::vector<SweepOutcome> outcomes;
  Progress progress("stress", static_cast<long>(points.size()), quiet, "points");
  for (size_t i = 0; i < points.size(); ++i) {
    std::string labels;
    for (size_t a = 0; a < spec.axes.size(); ++a) {
      labels += (a ? ", " : "") + spec.axes[a].name + " = " + points[i].labels[a];
    }
    if (!quiet) {
      std::fprintf(stderr, "stress: point %zu/%zu: %s\n", i + 1, points.size(), labels.c_str());
    }
    const fs::path dir = out / "points" / sweep_point_folder(i, points[i]);
    try {
      outcomes.push_back(run(points[i], dir));
    } catch (const Error& e) {
      SweepOutcome failed;
      failed.error = e.what();
      outcomes.push_back(std::move(failed));
      if (!quiet) std::fprintf(stderr, "stress: point %zu failed: %s\n", i + 1, e.what());
    }
    write_sweep_tables(spec, points, outcomes, out);
    progress.advance();
  }
  return outcomes;
}

}  // namespace simcap
