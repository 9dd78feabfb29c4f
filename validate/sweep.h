// Runs a stress sweep point by point through a caller-supplied closed loop and publishes the
// results: OUT/table.csv (deterministic), OUT/table.html with the plot, OUT/mpjpe.svg (MPJPE
// against the first varied parameter) and OUT/timings.csv (seconds per stage); with a 2D
// detector in the loop, its keypoint scores by visibility class too.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "validate/evaluation.h"
#include "validate/keypoint_scores.h"
#include "validate/sweep_spec.h"

namespace simcap {

struct SweepOutcome {
  std::optional<Evaluation> evaluation;              // empty when the point failed
  std::string error;                                 // why it failed
  std::filesystem::path report;                      // the point's report.html
  std::optional<KeypointScores> keypoints2d;         // the 2D detector's scores, if it had one
  std::filesystem::path report2d;                    // ... and their report.html
  double render_s = 0, track_s = 0, validate_s = 0;  // wall time of each stage
};

// Renders, tracks and validates one point into `point_dir`. A simcap::Error it throws marks the
// point failed (the sweep goes on); other exceptions end the sweep.
using SweepPointRunner =
    std::function<SweepOutcome(const SweepPoint& point, const std::filesystem::path& point_dir)>;

// Runs every point of `spec` into OUT/points/<nn>_<labels>/, rewriting the tables after each
// point so that an interrupted sweep still leaves the finished rows. Progress on stderr.
std::vector<SweepOutcome> run_sweep(const SweepSpec& spec, const std::filesystem::path& out,
                                    const SweepPointRunner& run, bool quiet);

// The tables and plot for the first `outcomes.size()` points.
void write_sweep_tables(const SweepSpec& spec, const std::vector<SweepPoint>& points,
                        const std::vector<SweepOutcome>& outcomes,
                        const std::filesystem::path& out);

// The table `simcap stress` prints: per point MPJPE, PA-MPJPE, PCK@100, failed frames, the worst
// joint and tracked frames/s, then a mean row and a worst row (each column's worst value; the
// worst joint of the point whose worst joint is furthest off). When points have 2D detector
// scores, a second table follows: COCO AP and, per visibility class (visible, self-occluded,
// scene-occluded), the median pixel error and the miss rate, and the left/right swap rate.
std::string sweep_table_text(const SweepSpec& spec, const std::vector<SweepPoint>& points,
                             const std::vector<SweepOutcome>& outcomes);

// Folder name of point `index`: its number and labels, reduced to [A-Za-z0-9._-].
std::string sweep_point_folder(size_t index, const SweepPoint& point);

}  // namespace simcap
