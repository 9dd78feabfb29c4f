#include "tracker/common/dataset.h"

#include <yaml-cpp/yaml.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>

#include "core/atomic_file.h"
#include "core/calibration.h"
#include "core/dataset_actors.h"
#include "core/error.h"
#include "core/loop_folder.h"
#include "tracker/common/png_decoder.h"

namespace simcap::tracker {
namespace fs = std::filesystem;

namespace {

// Frame number of "000123.png"; -1 for anything else.
int frame_number(const fs::path& file) {
  const std::string name = file.filename().string();
  if (name.size() != 10 || name.substr(6) != ".png") return -1;
  int n = 0;
  for (int i = 0; i < 6; ++i) {
    if (name[i] < '0' || name[i] > '9') return -1;
    n = n * 10 + (name[i] - '0');
  }
  return n;
}

std::string frame_file(int frame) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%06d.png", frame);
  return buf;
}

// A render that was killed (or still runs) leaves meta.json saying "complete": false and only its
// first frames on disk, which a tracker would otherwise take for the whole dataset.
void refuse_unfinished_render(const fs::path& root) {
  const fs::path meta = root / "meta.json";
  if (!fs::is_regular_file(meta)) return;
  const nlohmann::json parsed = nlohmann::json::parse(read_text(meta), nullptr, false);
  // Not simcap's meta.json: the tracker reads nothing else from it.
  if (parsed.is_discarded() || !parsed.is_object()) return;
  const auto complete = parsed.find("complete");
  if (complete != parsed.end() && complete->is_boolean() && !complete->get<bool>()) {
    throw Error(meta.string() +
                ": \"complete\": false: the render of this dataset did not finish (interrupted, "
                "or still running); complete it with simcap render SCENE -o " +
                root.string() + " --resume");
  }
}

}  // namespace

Dataset::Dataset(fs::path root, const std::string& actor) : root_(std::move(root)) {
  if (!fs::is_directory(root_)) {
    throw Error(root_.string() + ": not a folder (expected a dataset written by simcap render)");
  }
  refuse_loop_folder(root_, "dataset");
  refuse_unfinished_render(root_);
  const fs::path calibration = root_ / "calibration" / "opencv.yaml";
  if (!fs::is_regular_file(calibration)) {
    throw Error(calibration.string() +
                ": missing (expected the dataset's calibration; is this a simcap dataset?)");
  }
  cameras_ = read_opencv_calibration(calibration);
  if (cameras_.empty()) throw_input_error(calibration, 0, "camera_names", "lists no cameras");
  for (const Camera& cam : cameras_) {
    if (cam.width <= 0 || cam.height <= 0) {
      throw_input_error(calibration, 0, "camera '" + cam.name + "'", "has no image size");
    }
    if (!fs::is_directory(root_ / cam.name)) {
      throw Error((root_ / cam.name).string() + ": missing (the calibration lists camera '" +
                  cam.name + "')");
    }
  }
  actors_ = read_dataset_actors(root_);
  actor_ = find_actor(actors_, actor, "--actor");
}

std::vector<int> Dataset::frames(const std::string& kind) const {
  std::vector<int> reference;
  for (size_t c = 0; c < cameras_.size(); ++c) {
    const fs::path folder = root_ / cameras_[c].name / kind;
    if (!fs::is_directory(folder)) throw Error(folder.string() + ": missing");
    std::vector<int> found;
    for (const auto& entry : fs::directory_iterator(folder)) {
      const int n = frame_number(entry.path());
      if (n >= 0) found.push_back(n);
    }
    std::sort(found.begin(), found.end());
    if (found.empty()) throw Error(folder.string() + ": no frames (expected 000000.png, ...)");
    if (c == 0) {
      reference = std::move(found);
      continue;
    }
    if (found != reference) {
      std::vector<int> missing, extra;
      std::set_difference(reference.begin(), reference.end(), found.begin(), found.end(),
                          std::back_inserter(missing));
      std::set_difference(found.begin(), found.end(), reference.begin(), reference.end(),
                          std::back_inserter(extra));
      const std::string detail = !missing.empty() ? frame_file(missing.front()) + " is missing"
                                                  : frame_file(extra.front()) + " is extra";
      throw Error(folder.string() + ": frames differ from " +
                  (root_ / cameras_[0].name / kind).string() + " (" + detail + ")");
    }
  }
  return reference;
}

fs::path Dataset::image_path(int camera, const std::string& kind, int frame) const {
  return root_ / cameras_.at(camera).name / kind / frame_file(frame);
}

cv::Mat Dataset::read(const fs::path& path, int camera, int flags, int rows) const {
  // Decoding is the tracker's largest fixed cost (a mask and a colour image per camera and
  // frame): libpng without the Adler-32 pass, about twice as fast as the OpenImageIO path of
  // core/image_io.h.
  cv::Mat image = decode_png(path, flags, rows);
  if (image.empty()) {
    throw Error(path.string() + (fs::exists(path) ? ": cannot decode the image" : ": missing"));
  }
  const Camera& cam = cameras_.at(camera);
  if (image.cols != cam.width || image.rows != cam.height) {
    throw Error(path.string() + ": image is " + std::to_string(image.cols) + "x" +
                std::to_string(image.rows) + ", the calibration of '" + cam.name + "' says " +
                std::to_string(cam.width) + "x" + std::to_string(cam.height));
  }
  return image;
}

cv::Mat Dataset::mask(int camera, int frame) const {
  const fs::path path = image_path(camera, "mask", frame);
  cv::Mat m = read(path, camera, cv::IMREAD_UNCHANGED);
  if (m.channels() != 1) throw Error(path.string() + ": a mask must have one channel");
  if (m.depth() != CV_8U) m = m != 0;
  // Multi-actor masks hold each pixel's actor index + 1: the others are background here.
  if (actors_.size() > 1) m = m == actor_mask_label(actors_, actor_);
  return m;
}

cv::Mat Dataset::others(int camera, int frame) const {
  if (actors_.size() <= 1) return {};
  const cv::Mat m = read(image_path(camera, "mask", frame), camera, cv::IMREAD_UNCHANGED);
  return (m != 0) & (m != actor_mask_label(actors_, actor_));
}

cv::Mat Dataset::rgb(int camera, int frame, int rows) const {
  return read(image_path(camera, "rgb", frame), camera, cv::IMREAD_COLOR, rows);
}

cv::Mat Dataset::background(int camera) const {
  return read(root_ / "background" / (cameras_.at(camera).name + ".png"), camera, cv::IMREAD_COLOR);
}

bool Dataset::has_background(int camera) const {
  return fs::is_regular_file(root_ / "background" / (cameras_.at(camera).name + ".png"));
}

JointTrack Dataset::ground_truth(const std::string& needed_by) const {
  const fs::path path = ground_truth_path();
  if (!fs::is_regular_file(path))
    throw Error(path.string() + ": missing (needed by " + needed_by + ")");
  return actor_joints(read_joint_track(path), actors_, actor_);
}

std::optional<Eigen::AlignedBox3d> Dataset::room() const {
  const fs::path path = root_ / "scene.yaml";
  if (!fs::is_regular_file(path)) return std::nullopt;
  try {
    const YAML::Node size = YAML::LoadFile(path.string())["room"]["size"];
    if (!size || !size.IsSequence() || size.size() != 3) return std::nullopt;
    const Eigen::Vector3d s(size[0].as<double>(), size[1].as<double>(), size[2].as<double>());
    if (!(s.array() > 0).all()) return std::nullopt;
    return Eigen::AlignedBox3d(Eigen::Vector3d(-s.x() / 2, 0, -s.z() / 2),
                               Eigen::Vector3d(s.x() / 2, s.y(), s.z() / 2));
  } catch (const YAML::Exception& e) {
    throw_input_error(path, e.mark.line + 1, "room.size", e.msg);
  }
}

double Dataset::fps() const {
  const fs::path path = root_ / "scene.yaml";
  if (!fs::is_regular_file(path)) return 30.0;
  try {
    const YAML::Node fps = YAML::LoadFile(path.string())["render"]["fps"];
    return fps ? fps.as<double>() : 30.0;
  } catch (const YAML::Exception& e) {
    throw_input_error(path, e.mark.line + 1, "render.fps", e.msg);
  }
}

std::optional<std::string> Dataset::actor_limits() const {
  const fs::path path = root_ / "scene.yaml";
  if (!fs::is_regular_file(path)) return std::nullopt;
  try {
    const YAML::Node actors = YAML::LoadFile(path.string())["actors"];
    if (!actors || !actors.IsSequence() || static_cast<int>(actors.size()) <= actor_) {
      return std::nullopt;
    }
    const YAML::Node limits = actors[actor_]["limits"];
    if (!limits) return std::nullopt;
    return limits.as<std::string>();
  } catch (const YAML::Exception& e) {
    throw_input_error(path, e.mark.line + 1, "actors[" + std::to_string(actor_) + "].limits",
                      e.msg);
  }
}

}  // namespace simcap::tracker
