// The CSV reader of models/detections.h: one row per detected keypoint,
// frame,camera,person,keypoint,x,y,score.
#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "core/csv.h"
#include "core/error.h"
#include "models/detections.h"

namespace simcap {
namespace {

struct Row {
  int line = 0, frame = 0, camera = 0;
  long person = 0;
  std::string keypoint;
  DetectedKeypoint value;
};

// The smallest layout that names every keypoint used (COCO-17's names are BlazePose-33's too).
KeypointLayoutId layout_naming(const std::vector<Row>& rows, const std::filesystem::path& path) {
  std::optional<KeypointLayoutId> best;
  for (const auto& [name, id] : kKeypointLayouts) {
    const KeypointLayout& l = keypoint_layout(id);
    const bool all = std::all_of(rows.begin(), rows.end(),
                                 [&](const Row& r) { return l.index(r.keypoint) >= 0; });
    if (all && (!best || l.size() < keypoint_layout(*best).size())) best = id;
  }
  if (!best) {
    throw_input_error(path, 0, "column 'keypoint'",
                      "the names are not all of one layout (" + choices_text(kKeypointLayouts) +
                          "; see validate/README.md)");
  }
  return *best;
}

}  // namespace

Detections read_detections_csv(const std::filesystem::path& path,
                               const std::vector<std::string>& cameras, int frames,
                               std::optional<KeypointLayoutId> layout) {
  if (cameras.empty() || frames < 1) throw Error("detections: the dataset has no images");
  CsvReader csv(path, {"frame", "camera", "person", "keypoint", "x", "y", "score"});
  std::vector<Row> rows;
  while (csv.next()) {
    Row r;
    r.line = csv.line();
    const long frame = csv.integer(0);
    if (frame < 0 || frame >= frames) {
      csv.fail(0, "expected a frame 0.." + std::to_string(frames - 1));
    }
    r.frame = static_cast<int>(frame);
    const auto camera = std::find(cameras.begin(), cameras.end(), csv.text(1));
    if (camera == cameras.end())
      csv.fail(1, "\"" + csv.text(1) + "\" is not a camera of the dataset");
    r.camera = static_cast<int>(camera - cameras.begin());
    r.person = csv.integer(2);
    if (r.person < 0) csv.fail(2, "expected a person id >= 0");
    r.keypoint = csv.text(3);
    r.value = {csv.number(4), csv.number(5), csv.number(6)};
    if (!std::isfinite(r.value.x) || !std::isfinite(r.value.y) || !std::isfinite(r.value.score)) {
      csv.fail(4, "expected finite x, y and score");
    }
    rows.push_back(std::move(r));
  }
  const KeypointLayout& l = keypoint_layout(layout ? *layout : layout_naming(rows, path));
  Detections out(l.id, cameras, frames);
  // (frame, camera, person id) -> the person's index in its image; ids ascending.
  std::map<std::tuple<int, int, long>, size_t> slot;
  for (const Row& r : rows) slot.emplace(std::tuple{r.frame, r.camera, r.person}, 0);
  for (auto& [key, index] : slot) {
    auto& image = out.at(std::get<0>(key), std::get<1>(key));
    index = image.size();
    image.push_back({std::vector<DetectedKeypoint>(static_cast<size_t>(l.size())), 0.0});
  }
  std::map<std::tuple<int, int, long>, std::vector<bool>> seen;
  for (const Row& r : rows) {
    const int k = l.index(r.keypoint);
    if (k < 0) {
      throw_input_error(path, r.line, "column 'keypoint'",
                        "\"" + r.keypoint + "\" is not a keypoint of " + std::string(l.title));
    }
    const std::tuple key{r.frame, r.camera, r.person};
    auto& done = seen.try_emplace(key, static_cast<size_t>(l.size()), false).first->second;
    if (done[static_cast<size_t>(k)]) {
      throw_input_error(path, r.line, "column 'keypoint'",
                        "a second row for " + r.keypoint + " of this person in this image");
    }
    done[static_cast<size_t>(k)] = true;
    out.at(r.frame, r.camera)[slot.at(key)].keypoints[static_cast<size_t>(k)] = r.value;
  }
  for (int f = 0; f < frames; ++f) {
    for (int c = 0; c < static_cast<int>(cameras.size()); ++c) {
      for (DetectedPerson& p : out.at(f, c)) p.score = mean_keypoint_score(p);
    }
  }
  return out;
}

}  // namespace simcap
