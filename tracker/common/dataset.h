// A simcap dataset as the trackers read it (ARCHITECTURE.md "Dataset layout"): calibration,
// background plates, per-camera frames and ground truth, checked for missing or mismatched parts.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <filesystem>
#include <opencv2/core/mat.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/joint_track.h"

namespace simcap::tracker {

class Dataset {
 public:
  // Reads calibration/opencv.yaml and checks that a folder exists for every camera. Throws
  // Error naming what is missing. `actor` names the person the dataset is read for (masks,
  // ground truth, joint limits); empty: the first actor. A name scene.yaml does not list is an
  // Error listing the actors.
  explicit Dataset(std::filesystem::path root, const std::string& actor = {});

  const std::filesystem::path& root() const { return root_; }
  const std::vector<Camera>& cameras() const { return cameras_; }
  int camera_count() const { return static_cast<int>(cameras_.size()); }

  // Frame numbers with an image of `kind` ("mask", "rgb") for every camera, ascending. Throws
  // Error when a camera lacks the folder, has no frames, or its frames differ from cam 0's.
  std::vector<int> frames(const std::string& kind) const;

  std::filesystem::path image_path(int camera, const std::string& kind, int frame) const;
  // The actors scene.yaml lists (empty without one) and the index of the one read for.
  const std::vector<std::string>& actors() const { return actors_; }
  int actor() const { return actor_; }
  // The actor's own visible pixels, CV_8UC1 (nonzero = the actor; with several actors the
  // others are background). Checked against the calibrated image size.
  cv::Mat mask(int camera, int frame) const;
  // The other actors' pixels of the same mask (nonzero = someone else, who may hide the actor
  // there); an empty Mat when the dataset has one actor.
  cv::Mat others(int camera, int frame) const;
  // Colour frame, CV_8UC3 in the decoder's channel order (the same for rgb() and background()).
  // With `rows` >= 0 only its first `rows` rows are read; the rest are black.
  cv::Mat rgb(int camera, int frame, int rows = -1) const;
  cv::Mat background(int camera) const;
  // Whether the dataset has the camera's empty-room plate (background/camNN.png).
  bool has_background(int camera) const;

  std::filesystem::path ground_truth_path() const { return root_ / "gt" / "joints3d.csv"; }
  // The actor's joints of gt/joints3d.csv under their own names (core/dataset_actors.h); throws
  // Error naming the file when it is missing, saying what needs it.
  JointTrack ground_truth(const std::string& needed_by) const;

  // The room's interior from scene.yaml (room.size, centred on x = z = 0, floor at y = 0), when
  // the file says.
  std::optional<Eigen::AlignedBox3d> room() const;
  // The joint-limits file scene.yaml names for the actor (actors[i].limits), as written there
  // ("asset:<name>" or a path), when it names one.
  std::optional<std::string> actor_limits() const;
  // Frames per second from scene.yaml (render.fps), 30 when the file does not say.
  double fps() const;

 private:
  cv::Mat read(const std::filesystem::path& path, int camera, int flags, int rows = -1) const;
  std::filesystem::path root_;
  std::vector<Camera> cameras_;
  std::vector<std::string> actors_;
  int actor_ = 0;
};

}  // namespace simcap::tracker
