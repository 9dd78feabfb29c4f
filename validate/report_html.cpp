#include "validate/report_html.h"

#include <cmath>
#include <cstdio>
#include <utility>

#include "core/svg_plot.h"

namespace simcap {

namespace {

std::string fmt(const char* format, double v) {
  return html_number(format, v);
}

std::string row(const std::vector<std::string>& cells, const char* tag = "td") {
  return html_row(cells, tag);
}

std::string summary_table(const Evaluation& ev) {
  std::string s = "<table>\n";
  s += row({"Frames", std::to_string(ev.frames.size()) + " (" + std::to_string(ev.frames.front()) +
                          " to " + std::to_string(ev.frames.back()) + ")"});
  s += row({"Joints", std::to_string(ev.joints.size())});
  s += row({"<b>MPJPE</b>", "<b>" + fmt("%.1f", ev.mpjpe_mm) + " mm</b>"});
  s += row({"PA-MPJPE (similarity-aligned per frame)", fmt("%.1f", ev.pa_mpjpe_mm) + " mm"});
  for (const auto& p : ev.pck) {
    s +=
        row({"PCK @ " + fmt("%.0f", p.threshold_mm) + " mm", fmt("%.1f", 100 * p.fraction) + " %"});
  }
  s += row({"Per-point RMSE, mean over joints (Moschini Table 7.2; HumanEva, 3 cameras: 35.5 mm)",
            fmt("%.1f", ev.rmse_mean_mm) + " mm"});
  s +=
      row({"Mean error over wrists and elbows (Balan; G&oacute;mez J&aacute;uregui, monocular: "
           "80&ndash;120 mm)",
           fmt("%.1f", ev.wrists_elbows_mm) + " mm"});
  if (!ev.angles.empty()) {
    s += row({"Joint-angle RMSE, mean over " + std::to_string(ev.angles.size()) + " joints",
              fmt("%.3f", ev.angle_rmse_mean_rad) + " rad"});
  }
  const FailureSummary& f = ev.failures;
  s += row({"Failed frames (MPJPE &gt; " + fmt("%.0f", f.threshold_mm) + " mm)",
            std::to_string(f.failed_frames) + " (" + fmt("%.1f", 100 * f.failed_fraction) +
                " %) in " + std::to_string(f.episodes.size()) + " episodes"});
  s += row({"Time to recover (frames; mean / max over recovered episodes)",
            fmt("%.1f", f.mean_recovery_frames) + " / " + std::to_string(f.max_recovery_frames)});
  return s + "</table>\n";
}

// A plot in mm against the frame number of one value per frame for each of `series`.
LinePlot frame_plot(
    const Evaluation& ev, const char* title,
    const std::vector<std::pair<const char*, double (*)(const FrameScore&)>>& series) {
  LinePlot plot;
  plot.title = title;
  plot.x_label = "frame";
  plot.y_label = "mm";
  for (const auto& [name, value] : series) {
    PlotSeries s{name, {}, {}};
    for (const auto& f : ev.per_frame) {
      s.x.push_back(f.frame);
      s.y.push_back(value(f));
    }
    plot.series.push_back(std::move(s));
  }
  return plot;
}

std::string per_frame_plot(const Evaluation& ev) {
  LinePlot plot = frame_plot(ev, "Error per frame",
                             {{"MPJPE", [](const FrameScore& f) { return f.mpjpe_mm; }},
                              {"PA-MPJPE", [](const FrameScore& f) { return f.pa_mpjpe_mm; }}});
  plot.reference_y = ev.failures.threshold_mm;
  plot.reference_label = "failure threshold";
  return line_plot_svg(plot);
}

std::string per_joint_section(const Evaluation& ev) {
  BarChart chart;
  chart.title = "MPJPE per joint";
  chart.value_label = "mm";
  for (const auto& j : ev.per_joint) {
    chart.labels.push_back(j.joint);
    chart.values.push_back(j.mpjpe_mm);
  }
  std::string s = bar_chart_svg(chart);
  s += "<table>\n" + row({"joint", "MPJPE mm", "PA-MPJPE mm", "RMSE mm", "max mm"}, "th");
  for (const auto& j : ev.per_joint) {
    s += row({j.joint, fmt("%.1f", j.mpjpe_mm), fmt("%.1f", j.pa_mpjpe_mm), fmt("%.1f", j.rmse_mm),
              fmt("%.1f", j.max_mm)});
  }
  return s + "</table>\n";
}

// One camera: each error split into its component along the camera's ray through the true
// joint (depth, which one view cannot see) and across it (the image plane).
std::string camera_ray_section(const Evaluation& ev) {
  std::string s =
      "<h2>Depth ambiguity</h2>\n<p>One camera: each joint's error split into its component along "
      "the camera's ray through the true joint (depth, which a single view cannot see) and the "
      "component across it (the image plane). Mean over all joints and frames: along " +
      fmt("%.1f", ev.ray->along_mm) + " mm, across " + fmt("%.1f", ev.ray->across_mm) +
      " mm.</p>\n";
  s += line_plot_svg(frame_plot(
      ev, "Error along and across the camera ray per frame",
      {{"along the ray (depth)", [](const FrameScore& f) { return f.ray->along_mm; }},
       {"across the ray (image)", [](const FrameScore& f) { return f.ray->across_mm; }}}));
  s += "<table>\n" + row({"joint", "along the ray mm", "across the ray mm"}, "th");
  for (const auto& j : ev.per_joint) {
    s += row({j.joint, fmt("%.1f", j.ray->along_mm), fmt("%.1f", j.ray->across_mm)});
  }
  return s + "</table>\n";
}

std::string visibility_chart(const std::string& title, const std::vector<VisibilityGroup>& groups) {
  BarChart chart;
  chart.title = title;
  chart.value_label = "MPJPE, mm";
  for (const auto& g : groups) {
    chart.labels.push_back(g.label);
    chart.values.push_back(g.count > 0 ? g.mpjpe_mm : std::nan(""));
    chart.annotations.push_back("(" + std::to_string(g.count) + " joint-frames)");
  }
  return bar_chart_svg(chart);
}

std::string angles_section(const Evaluation& ev) {
  std::string s =
      "<h2>Joint angles</h2>\n<p>Angle of the rotation between the true and tracked "
      "local joint rotations, arccos((tr(R<sub>1</sub>R<sub>2</sub><sup>T</sup>) "
      "&minus; 1)/2) (Moschini eq. 7.1), over frames.</p>\n<table>\n";
  s += row({"joint", "RMSE rad", "mean rad", "max rad"}, "th");
  for (const auto& a : ev.angles) {
    s += row({a.joint, fmt("%.3f", a.rmse_rad), fmt("%.3f", a.mean_rad), fmt("%.3f", a.max_rad)});
  }
  return s + "</table>\n";
}

std::string failures_section(const Evaluation& ev) {
  const FailureSummary& f = ev.failures;
  std::string s = "<h2>Tracking failures</h2>\n<p>A frame fails when its MPJPE is above " +
                  fmt("%.0f", f.threshold_mm) +
                  " mm; the time to recover is the number of frames until it is back below.</p>\n";
  if (f.episodes.empty()) return s + "<p>No failures.</p>\n";
  s += "<table>\n" + row({"first frame", "frames", "recovered"}, "th");
  for (const auto& e : f.episodes) {
    s += row({std::to_string(e.first_frame), std::to_string(e.frames), e.recovered ? "yes" : "no"});
  }
  return s + "</table>\n";
}

std::string media_section(const ReportContent& c) {
  std::string s =
      "<h2>Overlays</h2>\n<p>True skeleton in green, tracked skeleton in red, projected "
      "with the dataset's calibration.</p>\n";
  int last_frame = -1;
  for (const auto& o : c.overlays) {
    if (o.frame != last_frame) {
      if (last_frame >= 0) s += "</div>\n";
      s += "<h3>Frame " + std::to_string(o.frame) + " (" + xml_escape(o.reason) +
           ")</h3>\n<div class=\"grid\">\n";
      last_frame = o.frame;
    }
    s += "<figure><img alt=\"" + xml_escape(o.camera) + "\" src=\"data:image/jpeg;base64," +
         base64_encode(o.jpeg) + "\"><figcaption>" + xml_escape(o.camera) +
         "</figcaption></figure>\n";
  }
  if (last_frame >= 0) s += "</div>\n";
  if (c.overlays.empty()) s += "<p>No overlay images were made.</p>\n";
  s += "<h2>Video</h2>\n";
  if (!c.video_file.empty()) {
    s += "<video controls src=\"" + xml_escape(c.video_file) + "\"></video>\n";
  }
  return s + "<p>" + xml_escape(c.video_note) + "</p>\n";
}

}  // namespace

std::string report_html(const Evaluation& ev, const ReportContent& c) {
  std::string s = report_page_start("simcap validation report") + "<p>Dataset: <code>" +
                  xml_escape(c.dataset) + "</code><br>Track: <code>" + xml_escape(c.track) +
                  "</code></p>\n<h2>Summary</h2>\n" + summary_table(ev) +
                  "<h2>Error over time</h2>\n" + per_frame_plot(ev) + "<h2>Error per joint</h2>\n" +
                  per_joint_section(ev);
  if (!ev.by_visible_cameras.empty()) {
    s += "<h2>Error against visibility</h2>\n<p>Each joint in each frame is grouped by the number "
         "of cameras that see it and by its worst occlusion over the cameras (from "
         "gt/joints2d.csv).</p>\n" +
         visibility_chart("MPJPE by cameras seeing the joint", ev.by_visible_cameras) +
         visibility_chart("MPJPE by occlusion", ev.by_occlusion);
  }
  if (ev.ray) s += camera_ray_section(ev);
  if (!ev.angles.empty()) s += angles_section(ev);
  s += failures_section(ev) + media_section(c) + "</body>\n</html>\n";
  return s;
}

}  // namespace simcap
