// The JSON readers of models/detections.h: COCO keypoint results and OpenPose's per-image files.
#include <algorithm>
#include <cctype>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/error.h"
#include "models/detections.h"

namespace simcap {
namespace {

using Json = nlohmann::json;

Json parse_json(const std::filesystem::path& path) {
  try {
    return Json::parse(read_text(path));
  } catch (const Json::exception& e) {
    // parse_error, and out_of_range for a number beyond double's range (1.7e500: a fuzzing
    // finding, tests/fuzz/regressions/detections_coco/).
    throw_input_error(path, 0, "", std::string("not valid JSON: ") + e.what());
  }
}

// Keypoints from [x, y, score] * K. The first person read fixes the layout when none is given.
DetectedPerson person_of(const Json& triples, const std::filesystem::path& path,
                         const std::string& field, std::optional<KeypointLayoutId>& layout) {
  if (!triples.is_array()) throw_input_error(path, 0, field, "expected an array of numbers");
  const int n = static_cast<int>(triples.size());
  if (!layout) {
    if (n % 3 != 0 || !layout_of_count(n / 3)) {
      throw_input_error(path, 0, field,
                        std::to_string(n) + " numbers are not x, y, score for " +
                            layout_counts_text() + " keypoints");
    }
    layout = layout_of_count(n / 3);
  }
  const int k = keypoint_layout(*layout).size();
  if (n != 3 * k) {
    throw_input_error(path, 0, field,
                      "expected " + std::to_string(3 * k) + " numbers (" + std::to_string(k) +
                          " keypoints x 3), got " + std::to_string(n));
  }
  DetectedPerson person;
  person.keypoints.resize(static_cast<size_t>(k));
  for (int i = 0; i < n; ++i) {
    const Json& v = triples[static_cast<size_t>(i)];
    if (!v.is_number()) {
      throw_input_error(path, 0, field + "[" + std::to_string(i) + "]",
                        std::string("expected a number, got ") + v.type_name());
    }
    DetectedKeypoint& kp = person.keypoints[static_cast<size_t>(i / 3)];
    (i % 3 == 0 ? kp.x : i % 3 == 1 ? kp.y : kp.score) = v.get<double>();
  }
  return person;
}

int camera_index(const std::vector<std::string>& cameras, const std::string& name) {
  const auto it = std::find(cameras.begin(), cameras.end(), name);
  return it == cameras.end() ? -1 : static_cast<int>(it - cameras.begin());
}

std::string camera_list(const std::vector<std::string>& cameras) {
  std::string s;
  for (const std::string& c : cameras) s += (s.empty() ? "" : ", ") + c;
  return s;
}

// The number that ends `text` (after its last non-digit); -1 when it does not end in a digit.
long trailing_number(const std::string& text) {
  size_t start = text.size();
  while (start > 0 && std::isdigit(static_cast<unsigned char>(text[start - 1]))) --start;
  if (start == text.size() || text.size() - start > 12) return -1;
  return std::stol(text.substr(start));
}

struct Image {
  int frame = 0, camera = 0;
};

// The image an entry names: image_id, or file_name "<...>/<camera>/rgb/<frame>.png".
Image image_of(const Json& entry, const std::filesystem::path& path, const std::string& field,
               const std::vector<std::string>& cameras, int frames) {
  const long n_cameras = static_cast<long>(cameras.size());
  if (entry.contains("image_id")) {
    const Json& id = entry["image_id"];
    if (!id.is_number_integer()) {
      throw_input_error(path, 0, field + ".image_id", "expected an integer");
    }
    const long v = id.get<long>();
    if (v < 1 || v > static_cast<long>(frames) * n_cameras) {
      throw_input_error(path, 0, field + ".image_id",
                        std::to_string(v) + " is not an image of this dataset (1 + frame x " +
                            std::to_string(n_cameras) + " + camera, frames 0.." +
                            std::to_string(frames - 1) + ")");
    }
    return {static_cast<int>((v - 1) / n_cameras), static_cast<int>((v - 1) % n_cameras)};
  }
  if (!entry.contains("file_name") || !entry["file_name"].is_string()) {
    throw_input_error(path, 0, field, "expected an integer image_id or a string file_name");
  }
  const std::filesystem::path file(entry["file_name"].get<std::string>());
  const std::string camera = file.parent_path().parent_path().filename().string();
  const long frame = trailing_number(file.stem().string());
  const int c = camera_index(cameras, camera);
  if (file.parent_path().filename() != "rgb" || c < 0 || frame < 0 || frame >= frames) {
    throw_input_error(path, 0, field + ".file_name",
                      "\"" + file.string() + "\" is not <camera>/rgb/<frame>.png of a camera (" +
                          camera_list(cameras) + ") and frame 0.." + std::to_string(frames - 1) +
                          " of this dataset");
  }
  return {static_cast<int>(frame), c};
}

void check_dataset(const std::vector<std::string>& cameras, int frames) {
  if (cameras.empty() || frames < 1) throw Error("detections: the dataset has no images");
}

}  // namespace

Detections read_coco_results(const std::filesystem::path& path,
                             const std::vector<std::string>& cameras, int frames,
                             std::optional<KeypointLayoutId> layout) {
  check_dataset(cameras, frames);
  const Json json = parse_json(path);
  if (!json.is_array()) {
    throw_input_error(path, 0, "", "expected COCO keypoint results: an array of detections");
  }
  std::vector<std::pair<Image, DetectedPerson>> people;
  for (size_t i = 0; i < json.size(); ++i) {
    const Json& entry = json[i];
    const std::string field = "[" + std::to_string(i) + "]";
    if (!entry.is_object()) throw_input_error(path, 0, field, "expected an object");
    const Image image = image_of(entry, path, field, cameras, frames);
    if (entry.contains("category_id") && entry["category_id"] != 1) {
      throw_input_error(path, 0, field + ".category_id", "expected 1 (person)");
    }
    if (!entry.contains("keypoints")) throw_input_error(path, 0, field, "has no keypoints");
    DetectedPerson person = person_of(entry["keypoints"], path, field + ".keypoints", layout);
    if (!entry.contains("score")) {
      person.score = mean_keypoint_score(person);
    } else if (entry["score"].is_number()) {
      person.score = entry["score"].get<double>();
    } else {
      throw_input_error(path, 0, field + ".score", "expected a number");
    }
    people.emplace_back(image, std::move(person));
  }
  Detections out(layout.value_or(KeypointLayoutId::coco17), cameras, frames);
  for (auto& [image, person] : people)
    out.at(image.frame, image.camera).push_back(std::move(person));
  return out;
}

Detections read_openpose_folder(const std::filesystem::path& folder,
                                const std::vector<std::string>& cameras, int frames,
                                std::optional<KeypointLayoutId> layout) {
  check_dataset(cameras, frames);
  std::vector<std::pair<Image, DetectedPerson>> people;
  for (size_t c = 0; c < cameras.size(); ++c) {
    const std::filesystem::path dir = folder / cameras[c];
    if (!std::filesystem::is_directory(dir)) {
      throw_input_error(dir, 0, "",
                        "no such folder: OpenPose detections need one folder per camera");
    }
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
      const std::string name = e.path().filename().string();
      if (e.is_regular_file() && name.ends_with("_keypoints.json")) files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    for (const std::filesystem::path& file : files) {
      const std::string name = file.filename().string();
      const long frame = trailing_number(name.substr(0, name.size() - 15));
      if (frame < 0 || frame >= frames) {
        throw_input_error(file, 0, "",
                          "the name is not <frame>_keypoints.json for a frame 0.." +
                              std::to_string(frames - 1) + " of this dataset");
      }
      const Json json = parse_json(file);
      if (!json.is_object() || !json.contains("people") || !json["people"].is_array()) {
        throw_input_error(file, 0, "people", "expected an array of people");
      }
      const Json& list = json["people"];
      for (size_t i = 0; i < list.size(); ++i) {
        const std::string field = "people[" + std::to_string(i) + "]";
        if (!list[i].is_object() || !list[i].contains("pose_keypoints_2d")) {
          throw_input_error(file, 0, field, "has no pose_keypoints_2d");
        }
        DetectedPerson person =
            person_of(list[i]["pose_keypoints_2d"], file, field + ".pose_keypoints_2d", layout);
        person.score = mean_keypoint_score(person);
        people.emplace_back(Image{static_cast<int>(frame), static_cast<int>(c)}, std::move(person));
      }
    }
  }
  Detections out(layout.value_or(KeypointLayoutId::body25), cameras, frames);
  for (auto& [image, person] : people)
    out.at(image.frame, image.camera).push_back(std::move(person));
  return out;
}

}  // namespace simcap
