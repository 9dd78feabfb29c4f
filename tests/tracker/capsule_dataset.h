// Test support: a small dataset in simcap's layout rendered analytically (the humanoid's bones
// as capsules seen by a ring of cameras), independent of the Embree renderer.
#pragma once

#include <filesystem>

namespace simcap::testing {

struct CapsuleDatasetSpec {
  int frames = 6;
  int cameras = 5;
  int width = 240;
  int height = 180;
};

// Writes calibration/opencv.yaml, background/camNN.png, camNN/{rgb,mask}/%06d.png and
// gt/joints3d.csv (every joint of build_humanoid()) for a person stepping forward.
void write_capsule_dataset(const std::filesystem::path& root, const CapsuleDatasetSpec& spec = {});

}  // namespace simcap::testing
