#include "tracker/unzueta/gesture_report.h"

#include <algorithm>
#include <cmath>

#include "core/html_page.h"

namespace simcap::tracker {
namespace {

std::string count_of(long part, long whole) {
  return std::to_string(part) + " of " + std::to_string(whole);
}

std::string scores_table(const GestureResults& r) {
  std::string s = "<table>\n";
  s += html_row({"Spotting: precision / recall / F1",
                 html_number("%.3f", r.precision) + " / " + html_number("%.3f", r.recall) +
                     " / <b>" + html_number("%.3f", r.f1) + "</b> (" +
                     count_of(r.matched, r.truth_count) + " true gestures found, " +
                     std::to_string(r.spotted) + " spotted)"});
  for (const auto& [kind, conf] : r.recognition) {
    s += html_row(
        {"Recognition of the found gestures, " + std::string(name_of(kGestureClassifiers, kind)),
         "<b>" + html_number("%.3f", conf.accuracy) + "</b> (" +
             count_of(conf.correct, conf.total) + ")"});
  }
  s += html_row({"Held poses (K-NN, frames outside spotted gestures)",
                 html_number("%.3f", r.poses.accuracy) + " (" +
                     count_of(r.poses.correct, r.poses.total) + ")"});
  s += html_row({"Per-limb label stream, labelled frames", html_number("%.3f", r.label_accuracy)});
  return s + "</table>\n";
}

std::string confusion_table(const Confusion& c) {
  std::vector<std::string> head = {"truth \\ predicted"};
  for (const auto& l : c.labels) head.push_back(xml_escape(l));
  std::string s = "<table>\n" + html_row(head, "th");
  for (size_t i = 0; i < c.labels.size(); ++i) {
    std::vector<std::string> cells = {xml_escape(c.labels[i])};
    for (size_t j = 0; j < c.counts[i].size(); ++j) {
      const long n = c.counts[i][j];
      const std::string v = n == 0 ? "" : std::to_string(n);
      cells.push_back(i == j ? "<b>" + v + "</b>" : v);
    }
    s += html_row(cells);
  }
  return s + "</table>\n";
}

// A horizontal bar at height `y` over each [first, last] frame stretch; NaN elsewhere breaks it.
PlotSeries stretches(const std::string& name, const std::vector<std::pair<int, int>>& spans,
                     double y) {
  PlotSeries s{name, {}, {}};
  for (const auto& [first, last] : spans) {
    s.x.insert(s.x.end(), {double(first), double(last), double(last)});
    s.y.insert(s.y.end(), {y, y, std::nan("")});
  }
  return s;
}

std::string limb_plot(const GestureCorpus& c, const CorpusGestures& g, size_t limb,
                      const GestureOptions& o) {
  const std::string& name = kGestureLimbs[limb];
  const std::vector<double> mean =
      history_mean(spotting_energy(c.signals.hand[limb], c.fps, o), o.spotting.history);
  LinePlot plot;
  plot.title =
      name + ": mean pseudo-energy of the last " + std::to_string(o.spotting.history) + " frames";
  plot.x_label = "frame";
  plot.y_label = "(m/s)\u00b2";
  PlotSeries energy{"mean pseudo-energy", {}, {}};
  for (size_t i = 0; i < mean.size(); ++i) {
    energy.x.push_back(c.signals.frames[i]);
    energy.y.push_back(mean[i]);
  }
  const double top =
      std::max(2 * o.spotting.threshold, *std::max_element(mean.begin(), mean.end()));
  std::vector<std::pair<int, int>> truth, spotted;
  for (const auto& t : c.truth) {
    if (t.limb == name && t.kind == "dynamic") truth.emplace_back(t.first_frame, t.last_frame);
  }
  for (const auto& s : g.spotted) {
    if (s.limb == name) spotted.emplace_back(s.first_frame, s.last_frame);
  }
  plot.series = {energy, stretches("true gestures", truth, 1.05 * top),
                 stretches("spotted", spotted, 0.98 * top)};
  plot.reference_y = o.spotting.threshold;
  plot.reference_label = "threshold";
  plot.width = 1000;
  return line_plot_svg(plot);
}

}  // namespace

std::string gestures_report_html(const std::vector<GestureCorpus>& corpora, const GestureResults& r,
                                 const GestureOptions& o) {
  std::string s = report_page_start("simcap gesture spotting and recognition");
  s += "<p>Unzueta 2009 ch. 5, leave-one-subject-out over " + std::to_string(corpora.size()) +
       " subjects: each subject's gestures are recognised by classifiers trained on the "
       "others. Spotting threshold " +
       html_number("%.3g", o.spotting.threshold) + " (m/s)&sup2; on the mean of the last " +
       std::to_string(o.spotting.history) + " pseudo-energies.</p>\n<h2>Scores</h2>\n" +
       scores_table(r);
  const auto knn = r.recognition.find(GestureClassifierKind::knn);
  if (knn != r.recognition.end()) {
    s += "<h2>Confusion of the found gestures (K-NN)</h2>\n" + confusion_table(knn->second);
  }
  for (size_t k = 0; k < corpora.size(); ++k) {
    const CorpusGestures& g = r.corpora[k];
    s += "<h2>" + xml_escape(g.name) + "</h2>\n<p>" + std::to_string(g.spotted.size()) +
         " spotted, " + count_of(g.matched, g.truth_count) + " true gestures found; held poses " +
         count_of(g.pose_correct, g.pose_frames) + " frames.</p>\n";
    for (size_t limb = 0; limb < kGestureLimbs.size(); ++limb) {
      s += limb_plot(corpora[k], g, limb, o);
    }
  }
  return s + "</body>\n</html>\n";
}

}  // namespace simcap::tracker
