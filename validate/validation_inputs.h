// What `simcap validate` reads: a dataset's ground truth (3D joints, per-camera visibility,
// calibration, optional joint rotations) and a tracker's output, checked against each other and
// aligned frame by frame. Every mismatch is an Error naming the file and what was expected.
#pragma once

#include <filesystem>
#include <vector>

#include "core/camera.h"
#include "validate/evaluation.h"

namespace simcap {

struct ValidationInputs {
  std::filesystem::path dataset, track;
  std::vector<Camera> cameras;  // from calibration/opencv.yaml, in file order
  double fps = 30.0;            // from the dataset's scene.yaml when it says so
  // Evaluated joints: the HE15 set first, then any other joint both sides have, in ground-truth
  // order. Frames: the track's, which are the ground truth's or their first N (a track made
  // with `simcap track --frames N`).
  EvaluationInput evaluation;
};

// Reads DATASET/gt/joints3d.csv, gt/joints2d.csv, calibration/opencv.yaml, TRACK/joints3d.csv and,
// when the track has angles.csv, DATASET/gt/angles.csv.
ValidationInputs load_validation_inputs(const std::filesystem::path& dataset,
                                        const std::filesystem::path& track);

}  // namespace simcap
