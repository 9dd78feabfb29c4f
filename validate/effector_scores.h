// Scores a track's 2D end-effector tracks (TRACK/effectors2d.csv, core/effector_track.h) against
// the dataset's projected joints (gt/joints2d.csv): pixel error, lost frames, error by visibility.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace simcap {

// Pixel errors of one group of samples; 0 when `count` is 0.
struct PixelErrors {
  long count = 0;
  double median_px = 0, mean_px = 0, p90_px = 0, max_px = 0;
};

struct EffectorScore {
  std::string camera, effector, joint;
  long frames = 0;  // frames of the evaluation
  long lost = 0;    // frames the track says `lost` or has no row for
  PixelErrors all;  // every frame not lost
  // Split by the joint's label in this camera (gt/joints2d.csv).
  PixelErrors visible, self_occluded;
};

struct EffectorScores {
  std::vector<EffectorScore> per_effector;  // in the order of first appearance in the track
  PixelErrors all, visible, self_occluded;  // pooled over effectors and cameras
  long frames = 0, lost = 0;                // effector-frames
  double lost_fraction = 0;
};

// Median, mean, 90th percentile (nearest rank) and maximum of `errors`.
PixelErrors pixel_errors(std::vector<double> errors);

// Empty when the track has no effectors2d.csv. `frames`: the evaluated frames; `cameras`: the
// dataset's camera names. A row for an unknown camera or joint, or one outside `frames`, is an
// Error naming the file.
std::optional<EffectorScores> score_effector_tracks(const std::filesystem::path& dataset,
                                                    const std::filesystem::path& track,
                                                    const std::vector<int>& frames,
                                                    const std::vector<std::string>& cameras);

}  // namespace simcap
