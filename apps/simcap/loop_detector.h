// The detect stage of `simcap loop --detector`: 2D keypoints of every camera of the rendered
// dataset, from MediaPipe (scripts/detect_mediapipe) or the truth plus noise, for triangulation.
#pragma once

#include <filesystem>

#include "core/name_table.h"
#include "validate/noisy_detections.h"

namespace simcap::cli {

enum class LoopDetector { none, mediapipe, truth_noise };
inline constexpr NameTable<LoopDetector, 3> kLoopDetectors{
    {{"none", LoopDetector::none},
     {"mediapipe", LoopDetector::mediapipe},
     {"truth-noise", LoopDetector::truth_noise}}};

// Writes the detections of `dataset` to `file` (COCO keypoint results): BlazePose-33 from
// MediaPipe, or COCO-17 from the truth with `noise`. Throws Error when the detector fails.
void run_loop_detector(LoopDetector detector, const std::filesystem::path& dataset,
                       const std::filesystem::path& file, const TruthNoise& noise, bool quiet);

}  // namespace simcap::cli
