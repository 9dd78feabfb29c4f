// A rendered dataset as one glTF file to scrub in Blender or a web viewer: the room and the
// occluders, the cameras as glTF cameras, and every actor's body animated by the ground truth.
#pragma once

#include <filesystem>

namespace simcap {

struct DatasetGltfSummary {
  int cameras = 0, actors = 0, frames = 0;
};

// Reads DATASET/scene.yaml (room, occluders, actors' bodies, fps), calibration/opencv.yaml and
// gt/angles.csv + gt/joints3d.csv (each frame's joint rotations and root positions), and writes
// `out` (binary glTF) atomically. Cameras look down their node's -Z (glTF's convention): yfov
// and aspect ratio come from fy and fx; the principal point and distortion, which glTF cannot
// state, are kept with the exact calibration (K, dist, R, t, width, height) in the camera
// node's extras. Each actor is a skinned body whose joint nodes carry one animation key per
// dataset frame at the scene's fps, so its joints move exactly through gt/joints3d.csv. Throws
// Error naming the file that is missing or malformed.
DatasetGltfSummary export_dataset_gltf(const std::filesystem::path& dataset,
                                       const std::filesystem::path& out);

}  // namespace simcap
