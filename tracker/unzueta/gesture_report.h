// The page `simcap gestures` writes beside gestures.json (OUT/report.html): the scores, and per
// subject and hand the pseudo-energy history against the threshold with the true and spotted
// gestures under it, so that a missed or split gesture can be seen where it happened.
#pragma once

#include <string>
#include <vector>

#include "tracker/unzueta/gesture_evaluation.h"

namespace simcap::tracker {

// `corpora` are the ones `results` were computed from, in the same order.
std::string gestures_report_html(const std::vector<GestureCorpus>& corpora,
                                 const GestureResults& results, const GestureOptions& options);

}  // namespace simcap::tracker
