#include "models/detections.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/error.h"

namespace simcap {

double mean_keypoint_score(const DetectedPerson& person) {
  double sum = 0;
  int n = 0;
  for (const DetectedKeypoint& k : person.keypoints) {
    if (k.score > 0) {
      sum += k.score;
      ++n;
    }
  }
  return n ? sum / n : 0.0;
}

Detections::Detections(KeypointLayoutId layout, std::vector<std::string> cameras, int frames)
    : layout_(layout),
      cameras_(std::move(cameras)),
      frames_(frames),
      images_(static_cast<size_t>(std::max(frames, 0)) * cameras_.size()) {}

const std::vector<DetectedPerson>& Detections::at(int frame, int camera) const {
  if (frame < 0 || frame >= frames_ || camera < 0 || camera >= static_cast<int>(cameras_.size())) {
    throw Error("detections: no image for frame " + std::to_string(frame) + ", camera " +
                std::to_string(camera));
  }
  return images_[static_cast<size_t>(frame) * cameras_.size() + static_cast<size_t>(camera)];
}

std::vector<DetectedPerson>& Detections::at(int frame, int camera) {
  return const_cast<std::vector<DetectedPerson>&>(std::as_const(*this).at(frame, camera));
}

int Detections::people() const {
  int n = 0;
  for (const auto& image : images_) n += static_cast<int>(image.size());
  return n;
}

DetectionFormat detection_format_of(const std::filesystem::path& path) {
  if (std::filesystem::is_directory(path)) return DetectionFormat::openpose;
  const std::string ext = path.extension().string();
  if (ext == ".json") return DetectionFormat::coco_json;
  if (ext == ".csv") return DetectionFormat::csv;
  throw Error(path.string() +
              ": not a detections file: expected a COCO results .json, a .csv or an OpenPose "
              "folder");
}

Detections read_detections(const std::filesystem::path& path,
                           const std::vector<std::string>& cameras, int frames,
                           std::optional<KeypointLayoutId> layout) {
  switch (detection_format_of(path)) {
    case DetectionFormat::coco_json:
      return read_coco_results(path, cameras, frames, layout);
    case DetectionFormat::openpose:
      return read_openpose_folder(path, cameras, frames, layout);
    case DetectionFormat::csv:
      return read_detections_csv(path, cameras, frames, layout);
  }
  throw Error("unknown detection format");
}

void write_coco_results(const Detections& d, const std::filesystem::path& path) {
  // Dividing by an integer power of ten prints the shortest decimal; multiplying by 1e-3 does not.
  const auto rounded = [](double v, double per_unit) {
    return std::round(v * per_unit) / per_unit;
  };
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  const int cameras = static_cast<int>(d.cameras().size());
  for (int f = 0; f < d.frames(); ++f) {
    for (int c = 0; c < cameras; ++c) {
      for (const DetectedPerson& p : d.at(f, c)) {
        nlohmann::ordered_json triples = nlohmann::ordered_json::array();
        for (const DetectedKeypoint& k : p.keypoints) {
          triples.push_back(rounded(k.x, 1e3));
          triples.push_back(rounded(k.y, 1e3));
          triples.push_back(rounded(k.score, 1e6));
        }
        out.push_back({{"image_id", 1 + static_cast<long>(f) * cameras + c},
                       {"category_id", 1},
                       {"keypoints", triples},
                       {"score", rounded(p.score, 1e6)}});
      }
    }
  }
  write_text_atomic(path, out.dump() + "\n");
}

}  // namespace simcap
