#include "validate/effector_scores.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <tuple>

#include "core/csv.h"
#include "core/effector_track.h"
#include "core/error.h"
#include "validate/visibility.h"

namespace simcap {
namespace fs = std::filesystem;

namespace {

struct Projected {
  double u = 0, v = 0;
  std::string label;
};

using Key = std::tuple<int, std::string, std::string>;  // frame, camera, joint

// The rows of gt/joints2d.csv for the (camera, joint) pairs in `wanted`.
std::map<Key, Projected> read_projections(
    const fs::path& file, const std::set<std::pair<std::string, std::string>>& wanted) {
  CsvReader csv(file, kJoints2dColumns);
  std::map<Key, Projected> out;
  while (csv.next()) {
    if (!wanted.count({csv.text(1), csv.text(2)})) continue;
    out[{static_cast<int>(csv.integer(0)), csv.text(1), csv.text(2)}] = {
        csv.number(3), csv.number(4), csv.text(6)};
  }
  return out;
}

struct Errors {
  std::vector<double> all, visible, self_occluded;
};

}  // namespace

PixelErrors pixel_errors(std::vector<double> errors) {
  PixelErrors p;
  p.count = static_cast<long>(errors.size());
  if (errors.empty()) return p;
  std::sort(errors.begin(), errors.end());
  const size_t n = errors.size();
  p.median_px = n % 2 ? errors[n / 2] : 0.5 * (errors[n / 2 - 1] + errors[n / 2]);
  p.mean_px = std::accumulate(errors.begin(), errors.end(), 0.0) / static_cast<double>(n);
  p.p90_px = errors[static_cast<size_t>(std::ceil(0.9 * static_cast<double>(n))) - 1];
  p.max_px = errors.back();
  return p;
}

std::optional<EffectorScores> score_effector_tracks(const fs::path& dataset, const fs::path& track,
                                                    const std::vector<int>& frames,
                                                    const std::vector<std::string>& cameras) {
  const fs::path file = track / "effectors2d.csv";
  if (!fs::exists(file)) return std::nullopt;
  const std::vector<EffectorSample> samples = read_effector_track(file);

  // Effectors in order of first appearance, each with its rows by frame.
  std::vector<std::tuple<std::string, std::string, std::string>> order;
  std::map<std::tuple<std::string, std::string, std::string>, std::map<int, const EffectorSample*>>
      rows;
  std::set<std::pair<std::string, std::string>> wanted;
  for (const auto& s : samples) {
    if (std::find(cameras.begin(), cameras.end(), s.camera) == cameras.end()) {
      throw_input_error(file, 0, "camera",
                        "unknown camera '" + s.camera + "'; expected one of the dataset's");
    }
    if (!std::binary_search(frames.begin(), frames.end(), s.frame)) {
      throw_input_error(file, 0, "frame",
                        "frame " + std::to_string(s.frame) + " is not among the evaluated frames");
    }
    const auto key = std::tuple{s.camera, s.effector, s.joint};
    if (!rows.count(key)) order.push_back(key);
    if (!rows[key].emplace(s.frame, &s).second) {
      throw_input_error(file, 0, "frame",
                        "effector '" + s.effector + "' repeated for camera " + s.camera +
                            " in frame " + std::to_string(s.frame));
    }
    wanted.insert({s.camera, s.joint});
  }
  const fs::path truth_file = dataset / "gt" / "joints2d.csv";
  const auto truth = read_projections(truth_file, wanted);

  EffectorScores out;
  Errors pooled;
  for (const auto& key : order) {
    const auto& [camera, effector, joint] = key;
    EffectorScore score{camera, effector, joint, static_cast<long>(frames.size()), 0, {}, {}, {}};
    Errors e;
    const auto& by_frame = rows[key];
    for (int frame : frames) {
      const auto row = by_frame.find(frame);
      if (row == by_frame.end() || row->second->lost) {
        ++score.lost;
        continue;
      }
      const auto t = truth.find({frame, camera, joint});
      if (t == truth.end()) {
        throw_input_error(truth_file, 0, "joint",
                          "no row for joint '" + joint + "' in camera " + camera + " at frame " +
                              std::to_string(frame) + "; " + file.string() + " tracks it");
      }
      const double d = std::hypot(row->second->u - t->second.u, row->second->v - t->second.v);
      e.all.push_back(d);
      if (t->second.label == "visible") e.visible.push_back(d);
      if (t->second.label == "self_occluded") e.self_occluded.push_back(d);
    }
    for (auto [from, to] : {std::pair{&e.all, &pooled.all}, std::pair{&e.visible, &pooled.visible},
                            std::pair{&e.self_occluded, &pooled.self_occluded}}) {
      to->insert(to->end(), from->begin(), from->end());
    }
    score.all = pixel_errors(e.all);
    score.visible = pixel_errors(e.visible);
    score.self_occluded = pixel_errors(e.self_occluded);
    out.frames += score.frames;
    out.lost += score.lost;
    out.per_effector.push_back(std::move(score));
  }
  out.all = pixel_errors(pooled.all);
  out.visible = pixel_errors(pooled.visible);
  out.self_occluded = pixel_errors(pooled.self_occluded);
  out.lost_fraction =
      out.frames ? static_cast<double>(out.lost) / static_cast<double>(out.frames) : 0;
  return out;
}

}  // namespace simcap
