// The printed result of gesture spotting and recognition, shared by `simcap gestures` and
// `simcap loop --subjects`: per corpus, the scores, the K-NN confusion and the last line.
#pragma once

#include <filesystem>
#include <string>

#include "tracker/unzueta/gesture_evaluation.h"

namespace simcap::cli {

// Ends with "spotting_f1=F recognition_accuracy=A" (K-NN), the line scripts read.
std::string gestures_summary_text(const tracker::GestureResults& results,
                                  const std::filesystem::path& out);

}  // namespace simcap::cli
