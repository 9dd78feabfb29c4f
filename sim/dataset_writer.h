// The dataset folder of ARCHITECTURE.md: the fixed files (scene.yaml, calibration, parts.json,
// background plates), each frame's images (one file each, written atomically, in parallel), and
// the ground-truth tables, streamed row by row so memory does not grow with the frame count.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/csv.h"
#include "core/image_io.h"
#include "scenes/scene.h"
#include "sim/animated_actors.h"
#include "sim/coco_keypoints.h"
#include "sim/ground_truth.h"
#include "sim/mask_boxes.h"
#include "sim/renderer.h"

namespace simcap {

class DatasetWriter {
 public:
  // Per camera the folder <root>/<camera name>/ holds rgb/, depth/, mask/, parts/ (and normal/
  // when `normals`), one %06d file per dataset frame.
  DatasetWriter(std::filesystem::path root, std::vector<std::string> camera_names, bool normals);
  ~DatasetWriter();

  const std::filesystem::path& root() const { return root_; }
  // `kind` is rgb, depth, mask, parts or normal.
  std::filesystem::path image_path(int camera, std::string_view kind, int frame) const;
  // True when every image file of the frame exists (files only ever appear complete).
  bool frame_complete(int frame) const;
  bool backgrounds_complete() const;

  // scene.yaml (scene_to_yaml), calibration/opencv.yaml, calibration/intri.yml + extri.yml
  // (EasyMocap), calibration/calibration.toml (Anipose, Pose2Sim), calibration/colmap/ (COLMAP
  // text model; image names are frame 0's RGB files), calibration/blender_cameras.py and
  // parts.json (the part labels of `skeleton`). With rig.calibration_error every calibration/
  // file states the perturbed cameras and gt/calibration.yaml the true ones.
  void write_fixed_files(const Scene& scene, const Skeleton& skeleton) const;
  void write_backgrounds(const std::vector<RenderedView>& views) const;
  void write_frame(int frame, const std::vector<RenderedView>& views) const;

  // Opens gt/joints3d.csv, gt/joints2d.csv, gt/angles.csv and gt/joints3d_h36m17.csv
  // (Human3.6M's 17 joints, its names, the joints3d.csv columns) and starts
  // gt/keypoints_coco.json (sim/coco_keypoints.h). Joint names are H-Anim names; with several
  // actors, the joints of every actor after the first are prefixed "<actor>/".
  void open_truth(const std::vector<PosedActor>& actors, const std::vector<Camera>& cameras);
  // `boxes`: each actor's box in each camera's mask of the frame, [camera][actor].
  void append_truth(const FrameTruth& truth, const std::vector<std::vector<MaskBox>>& boxes);
  // Publishes the tables; until then they exist only under temporary names.
  // gt/gestures.csv: actor,limb,kind,label,first_frame,last_frame per labelled stretch of a
  // motion (models/motion.h MotionLabel; frames inclusive). Not written when there are none.
  void write_gestures(const std::vector<ActorLabel>& labels,
                      const std::vector<PosedActor>& actors) const;
  void commit_truth();

 private:
  std::filesystem::path root_;
  std::vector<std::string> cameras_;
  std::vector<std::string> kinds_;
  std::vector<std::vector<std::string>> joint_names_;  // [actor][joint]
  std::vector<std::vector<std::string>> h36m_names_;   // [actor][keypoint]
  std::unique_ptr<CsvWriter> joints3d_, joints2d_, angles_, h36m_;
  std::unique_ptr<CocoKeypoints> coco_;
};

// Encoding of the dataset's images. CPU time per 640x480 image of studio4, measured with
// OpenImageIO 2.4 / OpenEXR 3.1: RGB PNG 8.2 ms with the defaults (zlib 6, adaptive filters),
// 1.9 ms unfiltered at zlib 1 (19 kB instead of 12 kB); mask and parts PNGs 2.8 -> 0.7 ms. The
// float depth EXR stays uncompressed: 1.24 MB in 2-7 ms, against 0.72 MB in ~18 ms with zip at
// zlib level 1 (lossless), ~21 ms at zip's default level and 0.63 MB in ~22 ms with piz; rle
// saves 0.3%. zip:1 costs studio4 a third of its frame rate on 2 cores (`simcap bench render`
// 12.4 -> 7.3 frames/s), below ARCHITECTURE.md's 10 frame sets per second, for 41% less disk.
inline const ImageCompression kDatasetCompression{1, false, "none"};

}  // namespace simcap
