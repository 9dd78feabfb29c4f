#include "validate/sweep.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <utility>

#include "core/atomic_file.h"
#include "core/csv.h"
#include "core/error.h"
#include "core/progress.h"
#include "core/svg_plot.h"

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

// The joint with the largest mean error.
const JointScore& worst_joint(const Evaluation& ev) {
  return *std::max_element(
      ev.per_joint.begin(), ev.per_joint.end(),
      [](const JointScore& a, const JointScore& b) { return a.mpjpe_mm < b.mpjpe_mm; });
}

// Tracked frames per second of wall time (the whole track stage, decoding included).
double track_fps(const SweepOutcome& o) {
  return o.evaluation && o.track_s > 0 ? o.evaluation->frames.size() / o.track_s : std::nan("");
}

// One table cell per metric, in the order of `kColumns`.
struct Column {
  const char* heading;
  bool lower_is_better;
  double (*value)(const SweepOutcome&);
  int decimals;
  double scale;  // shown as value x scale
  const char* unit;
};

const Column kColumns[] = {
    {"MPJPE mm", true, [](const SweepOutcome& o) { return o.evaluation->mpjpe_mm; }, 1, 1, ""},
    {"PA-MPJPE mm", true, [](const SweepOutcome& o) { return o.evaluation->pa_mpjpe_mm; }, 1, 1,
     ""},
    {"PCK@100", false, [](const SweepOutcome& o) { return pck_at(*o.evaluation, 100); }, 1, 100,
     "%"},
    {"failed", true, [](const SweepOutcome& o) { return o.evaluation->failures.failed_fraction; },
     1, 100, "%"},
    {"worst joint mm", true,
     [](const SweepOutcome& o) { return worst_joint(*o.evaluation).mpjpe_mm; }, 1, 1, ""},
    {"frames/s", false, track_fps, 1, 1, ""},
};

// The mean and the worst of each column over the points that ran; the worst row also names the
// worst joint of the point with the largest worst-joint error.
struct Summary {
  std::vector<double> mean, worst;
  std::string worst_joint;
};

std::optional<Summary> summarize(const std::vector<SweepOutcome>& outcomes) {
  std::vector<const SweepOutcome*> ran;
  for (const auto& o : outcomes) {
    if (o.evaluation) ran.push_back(&o);
  }
  if (ran.empty()) return std::nullopt;
  Summary s;
  for (const Column& c : kColumns) {
    double sum = 0, worst = c.value(*ran.front());
    for (const SweepOutcome* o : ran) {
      const double v = c.value(*o);
      sum += v;
      worst = c.lower_is_better ? std::max(worst, v) : std::min(worst, v);
    }
    s.mean.push_back(sum / ran.size());
    s.worst.push_back(worst);
  }
  const auto by_worst_joint = [](const SweepOutcome* a, const SweepOutcome* b) {
    return worst_joint(*a->evaluation).mpjpe_mm < worst_joint(*b->evaluation).mpjpe_mm;
  };
  s.worst_joint =
      worst_joint(*(*std::max_element(ran.begin(), ran.end(), by_worst_joint))->evaluation).joint;
  return s;
}

std::string cell(const Column& c, double v) {
  return std::isnan(v) ? "-" : fixed(v * c.scale, c.decimals) + c.unit;
}

std::string relative_report(const SweepOutcome& o, const fs::path& out) {
  return o.report.empty() ? "" : o.report.lexically_relative(out).generic_string();
}

// A sweep with a 2D detector in its loop gets the detector's columns (decided by the points, so
// that the header does not change when the first point fails).
bool has_detector(const std::vector<SweepPoint>& points) {
  return std::any_of(points.begin(), points.end(),
                     [](const SweepPoint& p) { return !p.config.detector.name.empty(); });
}

// The visibility classes of the 2D columns: -1 pools the in-frame ones, then visible,
// self-occluded, scene-occluded (out of frame is what the detector cannot see; a detection there
// is a guess the pool leaves out too).
constexpr std::array<int, 4> k2dClasses = {-1, 0, 1, 2};
const char* const k2dShort[] = {"all", "vis", "self", "scene"};

const KeypointGroup& group_2d(const KeypointScores& s, int c) {
  return c < 0 ? s.all : s.by_visibility[c];
}

std::string class_stem(int c) {
  return c < 0 ? "in_frame" : std::string(visibility_class_name(c));
}

// An empty cell for an empty group (NaN), as keypoints2d.csv writes it.
std::string csv_number(double v, int decimals) {
  return std::isnan(v) ? "" : fixed(v, decimals);
}

// One-camera sweeps split each error along and across the camera's rays (depth ambiguity).
bool has_ray_split(const std::vector<SweepOutcome>& outcomes) {
  return std::any_of(outcomes.begin(), outcomes.end(),
                     [](const SweepOutcome& o) { return o.evaluation && o.evaluation->ray; });
}

std::string text_number(double v, int decimals, double scale = 1, const char* unit = "") {
  return std::isnan(v) ? "-" : fixed(v * scale, decimals) + unit;
}

void write_csv(const SweepSpec& spec, const std::vector<SweepPoint>& points,
               const std::vector<SweepOutcome>& outcomes, const fs::path& out) {
  std::vector<std::string> columns = {"point"};
  for (const auto& a : spec.axes) columns.push_back(csv_cell(a.name));
  for (const char* c : {"status", "frames", "mpjpe_mm", "pa_mpjpe_mm", "pck_50mm", "pck_100mm",
                        "pck_150mm", "rmse_mean_mm", "wrists_elbows_mm", "failed_fraction",
                        "worst_joint", "worst_joint_mm", "report"}) {
    columns.push_back(c);
  }
  const bool detector = has_detector(points);
  if (detector) {
    columns.push_back("ap_2d");
    for (int c : k2dClasses) {
      for (const char* m : {"_miss_rate", "_median_px", "_pck_torso_0.2", "_swap_rate"}) {
        columns.push_back(class_stem(c) + m);
      }
    }
    columns.push_back("report2d");
  }
  const bool ray = has_ray_split(outcomes);
  if (ray) {
    columns.push_back("along_ray_mm");
    columns.push_back("across_ray_mm");
  }
  CsvWriter csv(out / "table.csv", columns);
  CsvWriter times(out / "timings.csv",
                  {"point", "render_s", "track_s", "validate_s", "track_frames_per_s"});
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
                << fixed(ev.failures.failed_fraction, 4) << ',' << worst_joint(ev).joint << ','
                << fixed(worst_joint(ev).mpjpe_mm, 2);
    } else {
      csv.out() << ",error: " << csv_cell(o.error) << ",,,,,,,,,,,";
    }
    csv.out() << ',' << relative_report(o, out);
    if (detector) {
      if (o.keypoints2d) {
        const KeypointScores& k = *o.keypoints2d;
        csv.out() << ',' << fixed(k.coco.ap, 4);
        for (int c : k2dClasses) {
          const KeypointGroup& g = group_2d(k, c);
          csv.out() << ',' << csv_number(g.miss_rate(), 4) << ',' << csv_number(g.median_px(), 2)
                    << ',' << csv_number(g.pck_torso(1), 4) << ',' << csv_number(g.swap_rate(), 4);
        }
        csv.out() << ','
                  << (o.report2d.empty() ? ""
                                         : o.report2d.lexically_relative(out).generic_string());
      } else {
        csv.out() << std::string(2 + 4 * k2dClasses.size(), ',');
      }
    }
    if (ray && o.evaluation && o.evaluation->ray) {
      csv.out() << ',' << fixed(o.evaluation->ray->along_mm, 2) << ','
                << fixed(o.evaluation->ray->across_mm, 2);
    } else if (ray) {
      csv.out() << ",,";
    }
    csv.out() << '\n';
    times.out() << i << ',' << fixed(o.render_s, 2) << ',' << fixed(o.track_s, 2) << ','
                << fixed(o.validate_s, 2) << ',';
    const double fps = track_fps(o);
    if (!std::isnan(fps)) times.out() << fixed(fps, 1);
    times.out() << '\n';
  }
  csv.commit();
  times.commit();
}

// One quantity a sweep plot draws against the first axis.
struct PlotMetric {
  const char* name;
  double (*value)(const Evaluation&);
};

const PlotMetric kMpjpe{"MPJPE", [](const Evaluation& e) { return e.mpjpe_mm; }};
const PlotMetric kPaMpjpe{"PA-MPJPE", [](const Evaluation& e) { return e.pa_mpjpe_mm; }};
const PlotMetric kAlongRay{"along the ray",
                           [](const Evaluation& e) { return e.ray ? e.ray->along_mm : NAN; }};
const PlotMetric kAcrossRay{"across the ray",
                            [](const Evaluation& e) { return e.ray ? e.ray->across_mm : NAN; }};

// `metrics` against the first axis: one series per metric and combination of the other axes'
// labels (in order of first appearance).
std::string plot_svg(const SweepSpec& spec, const std::vector<SweepPoint>& points,
                     const std::vector<SweepOutcome>& outcomes, const std::string& title,
                     const std::vector<PlotMetric>& metrics) {
  const SweepAxis& axis = spec.axes.front();
  LinePlot plot;
  plot.title = title + " against " + axis.name;
  plot.x_label = axis.name;
  plot.y_label = "mm";
  plot.markers = true;
  const bool numeric = axis.numeric();
  if (!numeric) plot.x_categories = axis.labels;
  std::map<std::vector<std::string>, size_t> series_of;
  const auto x_of = [&](const std::string& label) {
    const size_t k = std::find(axis.labels.begin(), axis.labels.end(), label) - axis.labels.begin();
    return numeric ? std::stod(label) : static_cast<double>(k);
  };
  for (size_t i = 0; i < outcomes.size(); ++i) {
    const std::vector<std::string> rest(points[i].labels.begin() + 1, points[i].labels.end());
    auto [it, added] = series_of.emplace(rest, plot.series.size());
    if (added) {
      std::string others;
      for (size_t a = 1; a < spec.axes.size(); ++a) {
        others += (a == 1 ? " (" : ", ") + spec.axes[a].name + " " + rest[a - 1];
      }
      if (!others.empty()) others += ")";
      for (const PlotMetric& m : metrics) plot.series.push_back({m.name + others, {}, {}});
    }
    const double x = x_of(points[i].labels.front());
    const auto& ev = outcomes[i].evaluation;
    for (size_t m = 0; m < metrics.size(); ++m) {
      plot.series[it->second + m].x.push_back(x);
      plot.series[it->second + m].y.push_back(ev ? metrics[m].value(*ev) : std::nan(""));
    }
  }
  return line_plot_svg(plot);
}

// "label / label / ..." of a point's axes, as the text tables show it.
std::string point_label(const SweepPoint& point) {
  std::string label;
  for (const auto& l : point.labels) label += (label.empty() ? "" : " / ") + l;
  return label;
}

std::string ray_value(const SweepOutcome& o, double RaySplit::*part) {
  return o.evaluation && o.evaluation->ray ? fixed((*o.evaluation->ray).*part, 1) : "-";
}

std::string html_table_ray(const SweepSpec& spec, const std::vector<SweepPoint>& points,
                           const std::vector<SweepOutcome>& outcomes) {
  std::string s =
      "<h2>Depth ambiguity</h2>\n<p>One camera: the mean error along the camera's ray through "
      "each true joint (depth) and across it (the image plane).</p>\n<table>\n<tr><th>#</th>";
  for (const auto& a : spec.axes) s += "<th>" + xml_escape(a.name) + "</th>";
  s += "<th>along the ray mm</th><th>across the ray mm</th></tr>\n";
  for (size_t i = 0; i < outcomes.size(); ++i) {
    s += "<tr><td>" + std::to_string(i) + "</td>";
    for (const auto& l : points[i].labels) s += "<td>" + xml_escape(l) + "</td>";
    s += "<td>" + ray_value(outcomes[i], &RaySplit::along_mm) + "</td><td>" +
         ray_value(outcomes[i], &RaySplit::across_mm) + "</td></tr>\n";
  }
  return s + "</table>\n" +
         plot_svg(spec, points, outcomes, "Error along and across the camera ray",
                  {kAlongRay, kAcrossRay});
}

std::string html_table(const SweepSpec& spec, const std::vector<SweepPoint>& points,
                       const std::vector<SweepOutcome>& outcomes, const fs::path& out) {
  std::string s = "<table>\n<tr><th>#</th>";
  for (const auto& a : spec.axes) s += "<th>" + xml_escape(a.name) + "</th>";
  s += "<th>MPJPE mm</th><th>PA-MPJPE mm</th><th>PCK@50</th><th>PCK@100</th><th>PCK@150</th>"
       "<th>RMSE mm</th><th>wrists+elbows mm</th><th>failed frames</th><th>worst joint</th>"
       "<th>frames/s</th><th>report</th></tr>\n";
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
            fixed(100 * ev.failures.failed_fraction, 1) + "%",
            worst_joint(ev).joint + " " + fixed(worst_joint(ev).mpjpe_mm, 1) + " mm",
            cell(kColumns[5], track_fps(o))}) {
        s += "<td>" + xml_escape(v) + "</td>";
      }
    } else {
      s += "<td colspan=\"10\">failed: " + xml_escape(o.error) + "</td>";
    }
    const std::string link = relative_report(o, out);
    s += "<td>" + (link.empty() ? "" : "<a href=\"" + xml_escape(link) + "\">report</a>") +
         "</td></tr>\n";
  }
  if (const auto sum = summarize(outcomes)) {
    // Only the columns the summary has; the others stay empty.
    const auto row = [&](const char* name, const std::vector<double>& v, const std::string& joint) {
      s += "<tr><th colspan=\"" + std::to_string(spec.axes.size() + 1) + "\">" + name + "</th>";
      s += "<td>" + cell(kColumns[0], v[0]) + "</td><td>" + cell(kColumns[1], v[1]) +
           "</td><td></td><td>" + cell(kColumns[2], v[2]) + "</td><td></td><td></td><td></td><td>" +
           cell(kColumns[3], v[3]) + "</td><td>" + xml_escape(joint) + cell(kColumns[4], v[4]) +
           " mm</td><td>" + cell(kColumns[5], v[5]) + "</td><td></td></tr>\n";
    };
    row("mean", sum->mean, "");
    row("worst", sum->worst, sum->worst_joint + " ");
  }
  return s + "</table>\n";
}

std::string html_table_2d(const SweepSpec& spec, const std::vector<SweepPoint>& points,
                          const std::vector<SweepOutcome>& outcomes, const fs::path& out) {
  std::string s =
      "<h2>2D keypoints of the detector</h2>\n<p>COCO AP over every image; per visibility class "
      "of the truth: keypoints missed, median pixel error of the detected ones, PCK at 0.2 of "
      "the torso, and left/right swaps.</p>\n<table>\n<tr><th>#</th>";
  for (const auto& a : spec.axes) s += "<th>" + xml_escape(a.name) + "</th>";
  s += "<th>AP</th>";
  for (int c : k2dClasses) {
    s += "<th colspan=\"4\">" + xml_escape(c < 0 ? "in frame" : class_stem(c)) + "</th>";
  }
  s += "<th>report</th></tr>\n<tr><th colspan=\"" + std::to_string(spec.axes.size() + 2) +
       "\"></th>";
  for (size_t c = 0; c < k2dClasses.size(); ++c) {
    s += "<th>missed</th><th>median px</th><th>PCK@0.2</th><th>swapped</th>";
  }
  s += "<th></th></tr>\n";
  for (size_t i = 0; i < outcomes.size(); ++i) {
    const SweepOutcome& o = outcomes[i];
    s += "<tr><td>" + std::to_string(i) + "</td>";
    for (const auto& l : points[i].labels) s += "<td>" + xml_escape(l) + "</td>";
    if (!o.keypoints2d) {
      s += "<td colspan=\"" + std::to_string(1 + 4 * k2dClasses.size()) +
           "\">-</td><td></td></tr>\n";
      continue;
    }
    s += "<td>" + fixed(o.keypoints2d->coco.ap, 3) + "</td>";
    for (int c : k2dClasses) {
      const KeypointGroup& g = group_2d(*o.keypoints2d, c);
      for (const std::string& v :
           {text_number(g.miss_rate(), 1, 100, "%"), text_number(g.median_px(), 2),
            text_number(g.pck_torso(1), 1, 100, "%"), text_number(g.swap_rate(), 1, 100, "%")}) {
        s += "<td>" + xml_escape(v) + "</td>";
      }
    }
    const std::string link =
        o.report2d.empty() ? "" : o.report2d.lexically_relative(out).generic_string();
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
  if (!c.detector.name.empty()) {
    s += ", detector " + c.detector.name;
    if (c.detector.name == "truth-noise") {
      s += " (" + fixed(c.detector.noise_px, 1) + " px, seed " + std::to_string(c.detector.seed) +
           ")";
    }
  }
  return s;
}

}  // namespace

std::string sweep_table_text(const SweepSpec& spec, const std::vector<SweepPoint>& points,
                             const std::vector<SweepOutcome>& outcomes) {
  std::string s;
  char buf[512];
  const auto line = [&](const std::string& label, const std::vector<std::string>& cells,
                        const std::string& joint) {
    std::snprintf(buf, sizeof buf, "  %-24s %9s %12s %8s %8s  %-16s %7s %9s\n", label.c_str(),
                  cells[0].c_str(), cells[1].c_str(), cells[2].c_str(), cells[3].c_str(),
                  joint.c_str(), cells[4].c_str(), cells[5].c_str());
    s += buf;
  };
  line(spec.axes.front().name, {"MPJPE mm", "PA-MPJPE mm", "PCK@100", "failed", "mm", "frames/s"},
       "worst joint");
  for (size_t i = 0; i < outcomes.size(); ++i) {
    const std::string label = point_label(points[i]);
    if (!outcomes[i].evaluation) {
      s += "  " + label + "  failed: " + outcomes[i].error + "\n";
      continue;
    }
    std::vector<std::string> cells;
    for (const Column& c : kColumns) cells.push_back(cell(c, c.value(outcomes[i])));
    line(label, cells, worst_joint(*outcomes[i].evaluation).joint);
  }
  if (const auto sum = summarize(outcomes)) {
    for (const auto& [name, values] : {std::pair{"mean", sum->mean}, {"worst", sum->worst}}) {
      std::vector<std::string> cells;
      for (size_t c = 0; c < values.size(); ++c) cells.push_back(cell(kColumns[c], values[c]));
      line(name, cells, std::string(name) == "worst" ? sum->worst_joint : "");
    }
  }
  if (has_ray_split(outcomes)) {
    s += "Depth ambiguity (one camera): mean error along and across the camera ray, mm\n";
    std::snprintf(buf, sizeof buf, "  %-24s %9s %9s\n", spec.axes.front().name.c_str(), "along",
                  "across");
    s += buf;
    for (size_t i = 0; i < outcomes.size(); ++i) {
      if (!outcomes[i].evaluation) continue;
      const std::string label = point_label(points[i]);
      std::snprintf(buf, sizeof buf, "  %-24s %9s %9s\n", label.c_str(),
                    ray_value(outcomes[i], &RaySplit::along_mm).c_str(),
                    ray_value(outcomes[i], &RaySplit::across_mm).c_str());
      s += buf;
    }
  }
  if (std::none_of(outcomes.begin(), outcomes.end(),
                   [](const SweepOutcome& o) { return o.keypoints2d.has_value(); })) {
    return s;
  }
  s += "2D keypoints of the detector: COCO AP; median px and missed by visibility class\n";
  const auto line2d = [&](const std::string& label, const std::vector<std::string>& cells) {
    std::snprintf(buf, sizeof buf, "  %-24s", label.c_str());
    s += buf;
    for (const std::string& c : cells) {
      std::snprintf(buf, sizeof buf, " %9s", c.c_str());
      s += buf;
    }
    s += '\n';
  };
  std::vector<std::string> heading = {"AP"};
  for (size_t c = 0; c < k2dClasses.size(); ++c)
    heading.push_back(std::string("px ") + k2dShort[c]);
  for (size_t c = 0; c < k2dClasses.size(); ++c)
    heading.push_back(std::string("miss ") + k2dShort[c]);
  heading.push_back("swapped");
  line2d(spec.axes.front().name, heading);
  for (size_t i = 0; i < outcomes.size(); ++i) {
    if (!outcomes[i].keypoints2d) continue;
    const KeypointScores& k = *outcomes[i].keypoints2d;
    const std::string label = point_label(points[i]);
    std::vector<std::string> cells = {fixed(k.coco.ap, 3)};
    for (int c : k2dClasses) cells.push_back(text_number(group_2d(k, c).median_px(), 2));
    for (int c : k2dClasses) cells.push_back(text_number(group_2d(k, c).miss_rate(), 1, 100, "%"));
    cells.push_back(text_number(k.all.swap_rate(), 1, 100, "%"));
    line2d(label, cells);
  }
  return s;
}

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
  const std::string svg =
      plot_svg(spec, points, outcomes, "MPJPE",
               spec.axes.size() == 1 ? std::vector{kMpjpe, kPaMpjpe} : std::vector{kMpjpe});
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
          html_table(spec, points, outcomes, out) + svg +
          (has_ray_split(outcomes) ? html_table_ray(spec, points, outcomes) : "") +
          (has_detector(points) ? html_table_2d(spec, points, outcomes, out) : "") +
          "</body>\n</html>\n");
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
