// `simcap gestures` as a library call: reads each (dataset, track) pair as one subject's corpus,
// scores spotting and recognition leave-one-subject-out (gesture_evaluation.h) and writes
// OUT/gestures.json and OUT/spotted.csv.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "tracker/unzueta/gesture_evaluation.h"

namespace simcap::tracker {

struct GestureSource {
  std::filesystem::path dataset;  // with gt/gestures.csv (one actor)
  std::filesystem::path track;    // with joints3d.csv (a track, or the dataset's gt/ folder)
};

// Reads the pair; Errors name the file (no gestures.csv, several actors, missing joints).
GestureCorpus load_gesture_corpus(const GestureSource& source);

GestureResults run_gestures(const std::vector<GestureSource>& sources,
                            const std::filesystem::path& out, const GestureOptions& options);

// The confusion matrix as an aligned text table (rows: truth, columns: predicted).
std::string confusion_text(const Confusion& c);

}  // namespace simcap::tracker
