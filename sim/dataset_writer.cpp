#include "sim/dataset_writer.h"

#include <oneapi/tbb/parallel_for.h>

#include <cstdio>
#include <nlohmann/json.hpp>
#include <ostream>

#include "core/atomic_file.h"
#include "core/blender_cameras.h"
#include "core/calibration.h"
#include "core/colmap_model.h"
#include "core/gesture_table.h"
#include "core/image_io.h"
#include "core/joint_track.h"
#include "core/toml_calibration.h"
#include "sim/calibration_error.h"

namespace simcap {
namespace fs = std::filesystem;
namespace {

const cv::Mat& image_of(const RenderedView& v, std::string_view kind) {
  if (kind == "rgb") return v.rgb;
  if (kind == "depth") return v.depth;
  if (kind == "mask") return v.mask;
  if (kind == "parts") return v.parts;
  return v.normal;
}

// ",<value>" with a fixed number of decimals, as printf's %.*f writes it ("nan" for NaN).
void put_number(std::ostream& out, double value, int decimals) {
  char text[512];
  std::snprintf(text, sizeof text, ",%.*f", decimals, value);
  out << text;
}

std::string frame_file(int frame, std::string_view kind) {
  char name[32];
  std::snprintf(name, sizeof name, "%06d.%s", frame,
                kind == "depth" || kind == "normal" ? "exr" : "png");
  return name;
}

}  // namespace

DatasetWriter::DatasetWriter(fs::path root, std::vector<std::string> camera_names, bool normals)
    : root_(std::move(root)), cameras_(std::move(camera_names)) {
  kinds_ = {"rgb", "depth", "mask", "parts"};
  if (normals) kinds_.push_back("normal");
}

DatasetWriter::~DatasetWriter() = default;

fs::path DatasetWriter::image_path(int camera, std::string_view kind, int frame) const {
  return root_ / cameras_.at(camera) / std::string(kind) / frame_file(frame, kind);
}

bool DatasetWriter::frame_complete(int frame) const {
  for (size_t c = 0; c < cameras_.size(); ++c) {
    for (const auto& kind : kinds_) {
      if (!fs::is_regular_file(image_path(static_cast<int>(c), kind, frame))) return false;
    }
  }
  return true;
}

bool DatasetWriter::backgrounds_complete() const {
  for (const auto& name : cameras_) {
    if (!fs::is_regular_file(root_ / "background" / (name + ".png"))) return false;
  }
  return true;
}

void DatasetWriter::write_fixed_files(const Scene& scene, const Skeleton& skeleton) const {
  write_text_atomic(root_ / "scene.yaml", scene_to_yaml(scene));
  const std::vector<Camera> calibration =
      written_calibration(scene.cameras, scene.calibration_error);
  write_opencv_calibration(root_ / "calibration" / "opencv.yaml", calibration);
  write_easymocap_calibration(root_ / "calibration" / "intri.yml",
                              root_ / "calibration" / "extri.yml", calibration);
  write_toml_calibration(root_ / "calibration" / "calibration.toml", calibration);
  std::vector<std::string> first_images;
  for (const std::string& name : cameras_) {
    first_images.push_back(name + "/rgb/" + frame_file(0, "rgb"));
  }
  write_colmap_model(root_ / "calibration" / "colmap", calibration, first_images);
  write_blender_cameras(root_ / "calibration" / "blender_cameras.py", calibration);
  if (scene.calibration_error.any()) {
    write_opencv_calibration(root_ / "gt" / "calibration.yaml", scene.cameras);
  }
  nlohmann::ordered_json parts;
  parts["description"] =
      "Pixel values of camNN/parts/*.png: 0 = background (no body), otherwise 1 + the skeleton "
      "index of the joint whose H-Anim segment the pixel shows.";
  parts["background"] = 0;
  parts["parts"] = nlohmann::ordered_json::array();
  for (int j = 0; j < skeleton.size(); ++j) {
    if (skeleton[j].is_site) continue;
    parts["parts"].push_back(
        {{"label", j + 1}, {"segment", skeleton[j].segment}, {"joint", skeleton[j].name}});
  }
  write_text_atomic(root_ / "parts.json", parts.dump(2) + "\n");
}

void DatasetWriter::write_gestures(const std::vector<ActorLabel>& labels,
                                   const std::vector<PosedActor>& actors) const {
  if (labels.empty()) return;
  CsvWriter csv(root_ / "gt" / "gestures.csv", kGesturesColumns);
  for (const ActorLabel& l : labels) {
    csv.out() << actors.at(l.actor).name << ',' << l.label.limb << ',' << l.label.kind << ','
              << l.label.label << ',' << l.first_frame << ',' << l.last_frame << '\n';
  }
  csv.commit();
}

void DatasetWriter::write_backgrounds(const std::vector<RenderedView>& views) const {
  tbb::parallel_for(size_t{0}, views.size(), [&](size_t c) {
    write_image(root_ / "background" / (cameras_.at(c) + ".png"), views[c].rgb,
                kDatasetCompression);
  });
}

void DatasetWriter::write_frame(int frame, const std::vector<RenderedView>& views) const {
  const size_t n = views.size() * kinds_.size();
  tbb::parallel_for(size_t{0}, n, [&](size_t i) {
    const size_t c = i / kinds_.size();
    const std::string& kind = kinds_[i % kinds_.size()];
    write_image(image_path(static_cast<int>(c), kind, frame), image_of(views[c], kind),
                kDatasetCompression);
  });
}

void DatasetWriter::open_truth(const std::vector<PosedActor>& actors,
                               const std::vector<Camera>& cameras) {
  joint_names_.clear();
  h36m_names_.clear();
  std::vector<std::string> actor_names;
  for (size_t a = 0; a < actors.size(); ++a) {
    auto& names = joint_names_.emplace_back();
    const std::string prefix = actors.size() > 1 && a > 0 ? actors[a].name + "/" : "";
    for (const int j : truth_joints(*actors[a].skeleton)) {
      names.push_back(prefix + (*actors[a].skeleton)[j].name);
    }
    auto& h36m = h36m_names_.emplace_back();
    if (actors[a].h36m17) {
      for (const BodyPoint& p : *actors[a].h36m17) h36m.push_back(prefix + p.name);
    }
    actor_names.push_back(actors[a].name);
  }
  h36m_ = std::make_unique<CsvWriter>(root_ / "gt" / "joints3d_h36m17.csv", kJoints3dColumns);
  coco_ = std::make_unique<CocoKeypoints>(cameras, std::move(actor_names));
  joints3d_ = std::make_unique<CsvWriter>(root_ / "gt" / "joints3d.csv", kJoints3dColumns);
  joints2d_ = std::make_unique<CsvWriter>(
      root_ / "gt" / "joints2d.csv",
      std::vector<std::string>{"frame", "camera", "joint", "u", "v", "depth", "visibility"});
  angles_ = std::make_unique<CsvWriter>(
      root_ / "gt" / "angles.csv",
      std::vector<std::string>{"frame", "joint", "qw", "qx", "qy", "qz"});
}

void DatasetWriter::append_truth(const FrameTruth& t,
                                 const std::vector<std::vector<MaskBox>>& boxes) {
  for (size_t a = 0; a < t.h36m_positions.size(); ++a) {
    for (size_t k = 0; k < t.h36m_positions[a].size(); ++k) {
      std::ostream& o = h36m_->out();
      o << t.frame << ',' << h36m_names_[a][k];
      for (int i = 0; i < 3; ++i) put_number(o, t.h36m_positions[a][k][i], 7);
      o << '\n';
    }
  }
  coco_->add_frame(t.frame, t.coco_views, boxes);
  for (size_t a = 0; a < t.positions.size(); ++a) {
    for (size_t j = 0; j < t.positions[a].size(); ++j) {
      const auto& p = t.positions[a][j];
      const auto& q = t.rotations[a][j];
      const std::string& name = joint_names_[a][j];
      std::ostream& o3 = joints3d_->out();
      o3 << t.frame << ',' << name;
      for (int k = 0; k < 3; ++k) put_number(o3, p[k], 7);
      o3 << '\n';
      std::ostream& oa = angles_->out();
      oa << t.frame << ',' << name;
      for (const double c : {q.w(), q.x(), q.y(), q.z()}) put_number(oa, c, 9);
      oa << '\n';
    }
  }
  std::ostream& o2 = joints2d_->out();
  for (size_t c = 0; c < t.views.size(); ++c) {
    for (size_t a = 0; a < t.views[c].size(); ++a) {
      for (size_t j = 0; j < t.views[c][a].size(); ++j) {
        const JointView& v = t.views[c][a][j];
        o2 << t.frame << ',' << cameras_[c] << ',' << joint_names_[a][j];
        put_number(o2, v.pixel.x(), 6);
        put_number(o2, v.pixel.y(), 6);
        put_number(o2, v.depth, 7);
        o2 << ',' << visibility_name(v.visibility) << '\n';
      }
    }
  }
}

void DatasetWriter::commit_truth() {
  joints3d_->commit();
  joints2d_->commit();
  angles_->commit();
  h36m_->commit();
  coco_->write(root_ / "gt" / "keypoints_coco.json");
}

}  // namespace simcap
