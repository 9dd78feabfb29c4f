// The effectors2d.csv table a tracker writes of its 2D end-effector tracks (Unzueta's head,
// hands, feet and pelvis): per frame, camera and effector the joint's pixel and the tracker state.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace simcap {

// u, v: the joint's estimated pixel; part_u, part_v: the tracked part's image position;
// state: tracking, occluded (predicted through an occlusion) or lost.
inline const std::vector<std::string> kEffectors2dColumns = {
    "frame", "camera", "effector", "joint", "u", "v", "part_u", "part_v", "state"};

struct EffectorSample {
  int frame = 0;
  std::string camera, effector, joint;
  double u = 0, v = 0;
  bool lost = false;
};

// Reads the table; an unknown state or a bad number is an Error naming file:line and column.
std::vector<EffectorSample> read_effector_track(const std::filesystem::path& path);

}  // namespace simcap
