#include "validate/keypoint_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/dataset_actors.h"
#include "core/svg_plot.h"
#include "validate/report_folder.h"
#include "validate/report_html.h"

namespace simcap {
namespace {

using Json = nlohmann::ordered_json;

// Fractions and pixels to 1e-7 and 1e-4; NaN (an empty group) as null.
Json unit(double v) {
  return std::isfinite(v) ? Json(std::round(v * 1e7) / 1e7) : Json(nullptr);
}
Json px(double v) {
  return std::isfinite(v) ? Json(std::round(v * 1e4) / 1e4) : Json(nullptr);
}

std::string fraction_label(const char* what, double f) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "pck_%s_%g", what, f);
  return buf;
}

Json group_json(const KeypointGroup& g) {
  Json j;
  j["keypoints"] = g.keypoints;
  j["detected"] = g.detected;
  j["miss_rate"] = unit(g.miss_rate());
  j["median_px"] = px(g.median_px());
  j["mean_px"] = px(g.mean_px());
  for (size_t i = 0; i < kTorsoFractions.size(); ++i) {
    j[fraction_label("torso", kTorsoFractions[i])] = unit(g.pck_torso(static_cast<int>(i)));
  }
  for (size_t i = 0; i < kHeightFractions.size(); ++i) {
    j[fraction_label("height", kHeightFractions[i])] = unit(g.pck_height(static_cast<int>(i)));
  }
  j["swap_checked"] = g.pairs;
  j["swap_rate"] = unit(g.swap_rate());
  return j;
}

Json classes_json(const std::array<KeypointGroup, kVisibilityClasses>& groups) {
  Json j = Json::object();
  for (int v = 0; v < kVisibilityClasses; ++v) {
    j[std::string(visibility_class_name(v))] = group_json(groups[v]);
  }
  return j;
}

std::string fmt(const char* format, double v) {
  return html_number(format, v);
}

std::string row(const std::vector<std::string>& cells, const char* tag = "td") {
  return html_row(cells, tag);
}

std::string group_row(const std::string& name, const KeypointGroup& g) {
  std::vector<std::string> cells = {name, std::to_string(g.keypoints),
                                    fmt("%.1f %%", 100 * g.miss_rate()), fmt("%.2f", g.median_px()),
                                    fmt("%.2f", g.mean_px())};
  for (int i = 0; i < static_cast<int>(kTorsoFractions.size()); ++i) {
    cells.push_back(fmt("%.1f %%", 100 * g.pck_torso(i)));
  }
  for (int i = 0; i < static_cast<int>(kHeightFractions.size()); ++i) {
    cells.push_back(fmt("%.1f %%", 100 * g.pck_height(i)));
  }
  cells.push_back(fmt("%.1f %%", 100 * g.swap_rate()));
  return row(cells);
}

std::string group_header(const std::string& first) {
  std::vector<std::string> cells = {first, "keypoints", "missed", "median px", "mean px"};
  for (const double f : kTorsoFractions) cells.push_back("PCK " + fmt("%g", f) + " torso");
  for (const double f : kHeightFractions) cells.push_back("PCK " + fmt("%g", f) + " height");
  cells.push_back("swapped");
  return row(cells, "th");
}

std::string class_chart(const KeypointScores& s, const std::string& title,
                        const std::string& unit_label, double (*value)(const KeypointGroup&)) {
  BarChart chart;
  chart.title = title;
  chart.value_label = unit_label;
  for (int v = 0; v < kVisibilityClasses; ++v) {
    const KeypointGroup& g = s.by_visibility[v];
    if (g.keypoints == 0) continue;
    chart.labels.emplace_back(visibility_class_name(v));
    chart.values.push_back(value(g));
    chart.annotations.push_back(std::to_string(g.keypoints) + " keypoints");
  }
  // An axis over nothing but zeros has no scale to show.
  if (std::none_of(chart.values.begin(), chart.values.end(), [](double v) { return v > 0; })) {
    return "<p>" + xml_escape(title) + ": 0 in every class.</p>\n";
  }
  return bar_chart_svg(chart);
}

std::string report_page(const KeypointScores& s, const std::string& dataset,
                        const std::string& detections) {
  const KeypointLayout& layout = keypoint_layout(s.layout);
  std::string h = report_page_start("simcap 2D keypoint report") + "<p>Dataset: <code>" +
                  xml_escape(dataset) + "</code><br>Detections: <code>" + xml_escape(detections) +
                  "</code> (" + std::string(layout.title) + ")<br>Actor: <code>" +
                  xml_escape(s.actor) + "</code></p>\n<h2>Summary</h2>\n<table>\n";
  h += row(
      {"COCO keypoint AP (OKS 0.50:0.95; every actor)", "<b>" + fmt("%.3f", s.coco.ap) + "</b>"});
  h += row({"AP at OKS 0.50 / 0.75", fmt("%.3f", s.coco.ap50) + " / " + fmt("%.3f", s.coco.ap75)});
  h += row({"AR (OKS 0.50:0.95)", fmt("%.3f", s.coco.ar)});
  h += row({"Images of the actor", std::to_string(s.images)});
  h += row({"... with no person detected / one / several",
            std::to_string(s.no_person) + " / " + std::to_string(s.one_person) + " / " +
                std::to_string(s.several_people)});
  h += row({"... several: the chosen one (highest OKS) is the top-scored",
            std::to_string(s.several_chosen_top) + " of " + std::to_string(s.several_people)});
  h += row({"... with people but none of OKS &ge; " + fmt("%g", kMinMatchOks) +
                " against the actor (all its keypoints missed)",
            std::to_string(s.unmatched)});
  h += row({"Left/right pairs swapped (in frame)",
            std::to_string(s.swapped_pairs) + " of " + std::to_string(s.swap_pairs)});
  h += "</table>\n<h2>By visibility</h2>\n<p>Each keypoint in each image is grouped by its "
       "label in the ground truth (gt/joints2d.csv, gt/keypoints_coco.json). <i>all</i> pools "
       "the classes in the frame.</p>\n<table>\n" +
       group_header("visibility") + group_row("all", s.all);
  for (int v = 0; v < kVisibilityClasses; ++v) {
    if (s.by_visibility[v].keypoints > 0) {
      h += group_row(std::string(visibility_class_name(v)), s.by_visibility[v]);
    }
  }
  h += "</table>\n<div class=\"grid\">\n" +
       class_chart(s, "PCK at 0.2 torso by visibility", "%",
                   [](const KeypointGroup& g) { return 100 * g.pck_torso(1); }) +
       class_chart(s, "Median error by visibility", "px",
                   [](const KeypointGroup& g) { return g.median_px(); }) +
       class_chart(s, "Missed by visibility", "%",
                   [](const KeypointGroup& g) { return 100 * g.miss_rate(); }) +
       class_chart(s, "Swapped left/right by visibility", "%",
                   [](const KeypointGroup& g) { return 100 * g.swap_rate(); }) +
       "</div>\n<h2>Per keypoint</h2>\n";
  BarChart per;
  per.title = "Median error per keypoint (in frame)";
  per.value_label = "px";
  std::string table = "<table>\n" + group_header("keypoint");
  for (int k = 0; k < layout.size(); ++k) {
    KeypointGroup in_frame;
    for (int v = 0; v < kVisibilityClasses; ++v) {
      if (v != static_cast<int>(VisibilityLabel::out_of_frame)) in_frame.add(s.per_keypoint[k][v]);
    }
    if (in_frame.keypoints == 0) continue;
    per.labels.emplace_back(layout.keypoints[k].name);
    per.values.push_back(in_frame.median_px());
    per.annotations.push_back(fmt("%.0f %% missed", 100 * in_frame.miss_rate()));
    table += group_row(std::string(layout.keypoints[k].name), in_frame);
  }
  h += bar_chart_svg(per) + table + "</table>\n</body>\n</html>\n";
  return h;
}

}  // namespace

std::string keypoint_scores_json(const KeypointScores& s, const std::string& dataset,
                                 const std::string& detections) {
  const KeypointLayout& layout = keypoint_layout(s.layout);
  Json j;
  j["schema"] = "simcap-keypoints2d/1";
  j["dataset"] = dataset;
  j["detections"] = detections;
  j["layout"] = name_of(kKeypointLayouts, s.layout);
  j["actor"] = s.actor;
  j["min_keypoint_score"] = s.min_keypoint_score;
  j["torso_fractions"] = kTorsoFractions;
  j["height_fractions"] = kHeightFractions;
  j["matching"] = {{"images", s.images},
                   {"no_person", s.no_person},
                   {"one_person", s.one_person},
                   {"several_people", s.several_people},
                   {"several_chosen_top_scored", s.several_chosen_top},
                   {"unmatched", s.unmatched},
                   {"min_match_oks", kMinMatchOks}};
  Json ap_at = Json::array(), recall_at = Json::array();
  for (int t = 0; t < CocoKeypointAp::kThresholds; ++t) {
    ap_at.push_back(unit(s.coco.ap_at[t]));
    recall_at.push_back(unit(s.coco.recall_at[t]));
  }
  j["coco"] = {{"ap", unit(s.coco.ap)},
               {"ap50", unit(s.coco.ap50)},
               {"ap75", unit(s.coco.ap75)},
               {"ar", unit(s.coco.ar)},
               {"ap_at", ap_at},
               {"recall_at", recall_at},
               {"truths", s.coco.truths},
               {"detections", s.coco.detections}};
  j["swap_pairs"] = s.swap_pairs;
  j["swapped_pairs"] = s.swapped_pairs;
  j["all"] = group_json(s.all);
  j["by_visibility"] = classes_json(s.by_visibility);
  Json per = Json::array();
  for (int k = 0; k < layout.size(); ++k) {
    const LayoutKeypoint& lk = layout.keypoints[k];
    if (lk.truth == TruthKind::none) continue;
    per.push_back({{"keypoint", lk.name},
                   {"truth", lk.truth_name},
                   {"by_visibility", classes_json(s.per_keypoint[k])}});
  }
  j["per_keypoint"] = per;
  return j.dump(2) + "\n";
}

std::string keypoint_scores_csv(const KeypointScores& s) {
  const KeypointLayout& layout = keypoint_layout(s.layout);
  std::string csv = "keypoint,visibility,keypoints,detected,miss_rate,median_px,mean_px";
  for (const double f : kTorsoFractions) csv += "," + fraction_label("torso", f);
  for (const double f : kHeightFractions) csv += "," + fraction_label("height", f);
  csv += ",swap_checked,swap_rate\n";
  const auto line = [&](const std::string& keypoint, const std::string& v, const KeypointGroup& g) {
    const Json j = group_json(g);
    csv += keypoint + "," + v;
    for (const auto& [key, value] : j.items()) csv += "," + (value.is_null() ? "" : value.dump());
    csv += "\n";
  };
  line("all", "in_frame", s.all);
  for (int v = 0; v < kVisibilityClasses; ++v) {
    line("all", std::string(visibility_class_name(v)), s.by_visibility[v]);
  }
  for (int k = 0; k < layout.size(); ++k) {
    if (layout.keypoints[k].truth == TruthKind::none) continue;
    for (int v = 0; v < kVisibilityClasses; ++v) {
      line(std::string(layout.keypoints[k].name), std::string(visibility_class_name(v)),
           s.per_keypoint[k][v]);
    }
  }
  return csv;
}

std::string keypoint_summary_text(const KeypointScores& s) {
  std::string t = "COCO AP " + fmt("%.3f", s.coco.ap) + " (AP50 " + fmt("%.3f", s.coco.ap50) +
                  ", AP75 " + fmt("%.3f", s.coco.ap75) + ", AR " + fmt("%.3f", s.coco.ar) +
                  "); actor " + s.actor + " in " + std::to_string(s.images) + " images, " +
                  std::to_string(s.no_person) + " without a person, " +
                  std::to_string(s.unmatched) + " without a match\n";
  t += "visibility       keypoints  missed   median px  PCK@0.2 torso  swapped\n";
  const auto line = [&](const std::string& name, const KeypointGroup& g) {
    const auto cell = [](const char* format, double v) {
      char buf[32];
      std::snprintf(buf, sizeof buf, format, v);
      return std::isfinite(v) ? std::string(buf) : std::string("-");
    };
    char buf[64];
    std::snprintf(buf, sizeof buf, "%-16s %9d", name.c_str(), g.keypoints);
    t += buf + ("  " + cell("%6.1f%%", 100 * g.miss_rate())) + "  " + cell("%9.2f", g.median_px()) +
         "  " + cell("%12.1f%%", 100 * g.pck_torso(1)) + "  " +
         cell("%6.1f%%", 100 * g.swap_rate()) + "\n";
  };
  line("all (in frame)", s.all);
  for (int v = 0; v < kVisibilityClasses; ++v) {
    if (s.by_visibility[v].keypoints > 0) {
      line(std::string(visibility_class_name(v)), s.by_visibility[v]);
    }
  }
  return t;
}

DetectionValidation validate_detections(const std::filesystem::path& dataset,
                                        const std::filesystem::path& detections,
                                        const std::filesystem::path& out,
                                        const DetectionValidateOptions& options) {
  check_report_folder(out);
  const KeypointTruth probe =
      read_keypoint_truth(dataset, options.layout.value_or(KeypointLayoutId::coco17));
  const Detections d = read_detections(detections, probe.cameras(), probe.frames(), options.layout);
  const KeypointTruth truth =
      d.layout() == probe.layout() ? probe : read_keypoint_truth(dataset, d.layout());
  DetectionValidation v;
  v.scores = score_keypoints(
      truth, d, {find_actor(truth.actors(), options.actor, "--actor"), options.min_keypoint_score});
  v.json = out / "keypoints2d.json";
  v.csv = out / "keypoints2d.csv";
  v.html = out / "report.html";
  const std::string json = keypoint_scores_json(v.scores, dataset.string(), detections.string());
  const std::string csv = keypoint_scores_csv(v.scores);
  const std::string html = report_page(v.scores, dataset.string(), detections.string());
  write_text_atomic(v.json, json);
  write_text_atomic(v.csv, csv);
  write_text_atomic(v.html, html);
  return v;
}

}  // namespace simcap
