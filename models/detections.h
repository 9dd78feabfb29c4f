// A 2D keypoint detector's output on a dataset: per frame and camera the people it found, each
// with its keypoints (x, y, score) in one layout; read from and written to detectors' formats.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/name_table.h"
#include "models/keypoint_layouts.h"

namespace simcap {

// Pixels as simcap's (the centre of the top-left pixel is (0, 0), as COCO's and OpenPose's).
// score 0 means not detected (COCO and OpenPose write such keypoints as 0, 0, 0).
struct DetectedKeypoint {
  double x = 0, y = 0, score = 0;
};

struct DetectedPerson {
  std::vector<DetectedKeypoint> keypoints;  // the layout's order
  double score = 0;
};

// The mean score of the keypoints detected (score above 0); 0 when none is: the person score of
// formats that give none.
double mean_keypoint_score(const DetectedPerson& person);

class Detections {
 public:
  Detections(KeypointLayoutId layout, std::vector<std::string> cameras, int frames);

  KeypointLayoutId layout() const { return layout_; }
  const std::vector<std::string>& cameras() const { return cameras_; }
  int frames() const { return frames_; }
  // The people found in camera `camera` (an index into cameras()) at frame `frame` (0-based).
  const std::vector<DetectedPerson>& at(int frame, int camera) const;
  std::vector<DetectedPerson>& at(int frame, int camera);
  // How many people over all images.
  int people() const;

 private:
  KeypointLayoutId layout_;
  std::vector<std::string> cameras_;
  int frames_;
  std::vector<std::vector<DetectedPerson>> images_;  // [frame * cameras + camera]
};

enum class DetectionFormat { coco_json, openpose, csv };
inline constexpr NameTable<DetectionFormat, 3> kDetectionFormats{
    {{"coco", DetectionFormat::coco_json},
     {"openpose", DetectionFormat::openpose},
     {"csv", DetectionFormat::csv}}};

// The format a path holds: a folder is OpenPose's, *.json COCO results, *.csv the CSV.
DetectionFormat detection_format_of(const std::filesystem::path& path);

// Reads detections of a dataset with these cameras (calibration order) and frames 0..frames-1.
// The layout is inferred (layout_of_count; for the CSV, the smallest layout naming every
// keypoint it uses) unless `layout` is given. A malformed file, an image outside the dataset or
// a keypoint count that does not fit the layout is an Error naming the file and the field.
//
// COCO keypoint results JSON: an array of {image_id or file_name, keypoints [x, y, score] * K,
// score, category_id (1 when present)}; image_id = 1 + frame * cameras + camera and file_name
// ends with "<camera>/rgb/<frame, 6 digits>.png", as in gt/keypoints_coco.json. A missing score
// is the mean of the keypoint scores above 0.
// OpenPose: a folder with one folder per camera holding <name>_keypoints.json files (the frame
// is the number that ends <name>: "000012" or "video_000000000012"), each
// {"people": [{"pose_keypoints_2d": [x, y, c] * K}]} in pixels (--keypoint_scale 0); the person
// score is the mean of the keypoint scores above 0.
// CSV: header frame,camera,person,keypoint,x,y,score; one row per detected keypoint; person is
// an integer id within the image, keypoint the layout's keypoint name; keypoints without a row
// are not detected; the person score is the mean of its keypoint scores above 0.
Detections read_detections(const std::filesystem::path& path,
                           const std::vector<std::string>& cameras, int frames,
                           std::optional<KeypointLayoutId> layout = std::nullopt);
Detections read_coco_results(const std::filesystem::path& path,
                             const std::vector<std::string>& cameras, int frames,
                             std::optional<KeypointLayoutId> layout = std::nullopt);
Detections read_openpose_folder(const std::filesystem::path& folder,
                                const std::vector<std::string>& cameras, int frames,
                                std::optional<KeypointLayoutId> layout = std::nullopt);
Detections read_detections_csv(const std::filesystem::path& path,
                               const std::vector<std::string>& cameras, int frames,
                               std::optional<KeypointLayoutId> layout = std::nullopt);

// COCO keypoint results JSON (readable by pycocotools' loadRes): one entry per person in frame,
// camera, person order with image_id, category_id 1, keypoints and score; pixels rounded to
// 1e-3, scores to 1e-6. Written atomically.
void write_coco_results(const Detections& detections, const std::filesystem::path& path);

}  // namespace simcap
