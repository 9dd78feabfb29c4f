// Reading and writing the scene keys of capture nuisances (rig.calibration_error, rig.sync,
// rig.readout_ms, rig.auto_exposure, lights[i].keyframes), kept apart from the loader and writer
// of the scene's other keys.
#pragma once

#include <yaml-cpp/yaml.h>

#include <vector>

#include "scenes/scene.h"
#include "scenes/yaml_field.h"

namespace simcap {

// Takes the rig's nuisance keys out of `rig` (the cameras already read) into `scene`.
void read_capture_keys(yaml::Map& rig, const std::vector<Camera>& cameras, Scene& scene);
// `lights[i].keyframes` of a light of the given kind.
std::vector<LightKeyframe> read_light_keyframes(const yaml::Field& f, Light::Kind kind);

// The same keys into an open rig map / light map; nothing when they are off.
void write_capture_keys(YAML::Emitter& out, const Scene& scene);
void write_light_keyframes(YAML::Emitter& out, const Light& light);

}  // namespace simcap
