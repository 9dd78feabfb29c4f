#include "tracker/unzueta/gesture_job.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/csv.h"
#include "core/error.h"
#include "core/joint_track.h"
#include "core/track_source.h"
#include "tracker/common/dataset.h"
#include "tracker/unzueta/gesture_report.h"

namespace simcap::tracker {
namespace fs = std::filesystem;

namespace {

using Json = nlohmann::ordered_json;

double rounded(double v) {
  return std::round(v * 1e7) / 1e7;
}

Json confusion_json(const Confusion& c) {
  return {{"total", c.total},
          {"correct", c.correct},
          {"accuracy", rounded(c.accuracy)},
          {"labels", c.labels},
          {"counts", c.counts}};
}

}  // namespace

GestureCorpus load_gesture_corpus(const GestureSource& source) {
  const fs::path table = source.dataset / "gt" / "gestures.csv";
  if (!fs::is_regular_file(table)) {
    throw_input_error(table, 0, "",
                      "missing; expected the labelled gestures of a dataset rendered from a "
                      "gesture corpus (e.g. scenes/gestures.yaml), with frames enough to hold "
                      "a whole gesture (render --frames or render.first_frame may leave them "
                      "all out)");
  }
  const fs::path joints = source.track / "joints3d.csv";
  if (!fs::is_regular_file(joints)) {
    throw_input_error(joints, 0, "", "missing; expected a track written by simcap track");
  }
  check_track_source(source.dataset, source.track);
  GestureCorpus c;
  c.name = source.track.string();
  c.fps = Dataset(source.dataset).fps();
  c.truth = read_gesture_table(table);
  for (const auto& g : c.truth) {
    if (g.actor != c.truth.front().actor) {
      throw_input_error(table, 0, "actor",
                        "labels for actors '" + c.truth.front().actor + "' and '" + g.actor +
                            "'; expected one actor (the one the track follows)");
    }
  }
  c.signals = body_signals(read_joint_track(joints), joints.string());
  return c;
}

std::string confusion_text(const Confusion& c) {
  size_t width = 5;
  for (const auto& l : c.labels) width = std::max(width, l.size());
  std::string s;
  char cell[64];
  std::snprintf(cell, sizeof cell, "%-*s", static_cast<int>(width), "truth\\pred");
  s += cell;
  for (size_t j = 0; j < c.labels.size(); ++j) {
    const std::string& l = c.labels[j];
    const std::string shortname = l.substr(l.find(':') + 1);
    std::snprintf(cell, sizeof cell, " %5.5s", shortname.c_str());
    s += cell;
  }
  s += "\n";
  for (size_t i = 0; i < c.labels.size(); ++i) {
    std::snprintf(cell, sizeof cell, "%-*s", static_cast<int>(width), c.labels[i].c_str());
    s += cell;
    for (long n : c.counts[i]) {
      std::snprintf(cell, sizeof cell, " %5ld", n);
      s += cell;
    }
    s += "\n";
  }
  return s;
}

GestureResults run_gestures(const std::vector<GestureSource>& sources, const fs::path& out,
                            const GestureOptions& options) {
  std::vector<GestureCorpus> corpora;
  for (const auto& s : sources) corpora.push_back(load_gesture_corpus(s));
  const GestureResults r = evaluate_gestures(corpora, options);

  fs::create_directories(out);
  CsvWriter csv(out / "spotted.csv", {"corpus", "limb", "first_frame", "last_frame", "path_first",
                                      "path_last", "truth", "iou", "knn", "svm"});
  Json corpora_json = Json::array();
  for (const auto& c : r.corpora) {
    for (const auto& g : c.spotted) {
      auto predicted = [&](GestureClassifierKind k) {
        const auto it = g.predicted.find(k);
        return it == g.predicted.end() ? std::string() : it->second;
      };
      char iou[32];
      std::snprintf(iou, sizeof iou, "%.4f", g.iou);
      csv.out() << c.name << ',' << g.limb << ',' << g.first_frame << ',' << g.last_frame << ','
                << g.path_first << ',' << g.path_last << ',' << g.truth << ',' << iou << ','
                << predicted(GestureClassifierKind::knn) << ','
                << predicted(GestureClassifierKind::svm) << '\n';
    }
    corpora_json.push_back({{"track", c.name},
                            {"spotted", c.spotted.size()},
                            {"truth_gestures", c.truth_count},
                            {"matched", c.matched},
                            {"pose_frames", c.pose_frames},
                            {"pose_correct", c.pose_correct},
                            {"label_frames", c.label_frames},
                            {"label_correct", c.label_correct}});
  }
  csv.commit();

  Json j;
  j["schema"] = "simcap-gestures/1";
  j["parameters"] = {{"smooth_sigma_frames", options.smooth_sigma},
                     {"history_frames", options.spotting.history},
                     {"threshold", options.spotting.threshold},
                     {"min_frames", options.spotting.min_frames},
                     {"drop_largest", options.spotting.drop_largest},
                     {"delay_at_end", options.spotting.delay_at_end},
                     {"velocity_median_frames", options.spotting.velocity_median},
                     {"states", options.states},
                     {"size", options.size},
                     {"k", options.k},
                     {"match_iou", options.match_iou}};
  j["corpora"] = corpora_json;
  j["spotting"] = {{"spotted", r.spotted},        {"truth_gestures", r.truth_count},
                   {"matched", r.matched},        {"precision", rounded(r.precision)},
                   {"recall", rounded(r.recall)}, {"f1", rounded(r.f1)}};
  Json rec;
  for (const auto& [kind, conf] : r.recognition) {
    rec[std::string(name_of(kGestureClassifiers, kind))] = confusion_json(conf);
  }
  j["recognition"] = rec;
  j["poses"] = confusion_json(r.poses);
  j["label_accuracy"] = rounded(r.label_accuracy);
  write_text_atomic(out / "gestures.json", j.dump(2) + "\n");
  write_text_atomic(out / "report.html", gestures_report_html(corpora, r, options));
  return r;
}

}  // namespace simcap::tracker
