// The metrics.json document of `simcap validate`: an Evaluation as JSON in the stable schema
// "simcap-metrics/1" documented field by field in validate/README.md.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "validate/effector_scores.h"
#include "validate/evaluation.h"

namespace simcap {

inline constexpr const char* kMetricsSchema = "simcap-metrics/1";

// Every metric of `ev`, after the "dataset" and "track" members naming the inputs; the caller
// adds "media". Millimetre
// values are rounded to 0.1 micrometre and fractions/radians to 1e-7 so that the file reads well
// and stays byte-identical across runs.
nlohmann::ordered_json metrics_to_json(const Evaluation& ev, const std::string& dataset,
                                       const std::string& track);

// The "effectors2d" member: the 2D end-effector scores, or null when the track has none.
nlohmann::ordered_json effector_scores_json(const std::optional<EffectorScores>& scores);

}  // namespace simcap
