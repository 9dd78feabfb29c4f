// The few numbers a person reads first, as an aligned plain-text table for the terminal:
// printed by `simcap validate`, `simcap loop` and `simcap demo`.
#pragma once

#include <string>

#include "validate/effector_scores.h"
#include "validate/evaluation.h"

namespace simcap {

// One "  name  value" line per headline metric, each ending in a newline.
std::string metrics_summary_text(const Evaluation& ev);
// The 2D end-effector lines (median pixel error, through self-occlusion, lost frames).
std::string effector_summary_text(const EffectorScores& scores);

}  // namespace simcap
