#include "apps/simcap/gesture_summary.h"

#include <cstdio>

#include "tracker/unzueta/gesture_job.h"

namespace simcap::cli {

std::string gestures_summary_text(const tracker::GestureResults& r,
                                  const std::filesystem::path& out) {
  std::string s;
  char buf[512];
  const auto line = [&](const char* format, auto... values) {
    std::snprintf(buf, sizeof buf, format, values...);
    s += buf;
  };
  line("simcap gestures: %zu corpora, leave-one-subject-out\n", r.corpora.size());
  for (const auto& c : r.corpora) {
    line("  %s: %zu spotted, %ld of %ld true gestures found, held poses %ld/%ld\n", c.name.c_str(),
         c.spotted.size(), c.matched, c.truth_count, c.pose_correct, c.pose_frames);
  }
  line("  spotting precision %.3f recall %.3f F1 %.3f\n", r.precision, r.recall, r.f1);
  for (const auto& [kind, conf] : r.recognition) {
    line("  recognition %s: %ld/%ld = %.3f\n",
         std::string(name_of(tracker::kGestureClassifiers, kind)).c_str(), conf.correct, conf.total,
         conf.accuracy);
  }
  line("  held poses (knn): %ld/%ld = %.3f\n", r.poses.correct, r.poses.total, r.poses.accuracy);
  line("  per-limb label stream: %.3f of labelled frames\n", r.label_accuracy);
  const auto knn = r.recognition.find(tracker::GestureClassifierKind::knn);
  if (knn != r.recognition.end()) {
    s += "confusion (knn):\n" + tracker::confusion_text(knn->second);
  }
  s += "report: " + (out / "report.html").string() + "\n";
  s += "scores: " + (out / "gestures.json").string() + "\n";
  line("spotting_f1=%.4f recognition_accuracy=%.4f\n", r.f1,
       knn == r.recognition.end() ? 0.0 : knn->second.accuracy);
  return s;
}

}  // namespace simcap::cli
