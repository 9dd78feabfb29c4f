#include <yaml-cpp/yaml.h>

#include <numbers>

#include "models/shipped_assets.h"
#include "scenes/capture_keys.h"
#include "scenes/scene.h"
#include "scenes/scene_names.h"
#include "scenes/yaml_field.h"

namespace simcap {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

// Numbers are written as the shortest text that reads back exactly, so that the round trip
// through a file is lossless and the text is the same on every run.
template <typename T>
void number(YAML::Emitter& out, std::string_view key, T v) {
  out << YAML::Key << std::string(key) << YAML::Value << yaml::format_number(v);
}

void text(YAML::Emitter& out, std::string_view key, const std::string& v) {
  out << YAML::Key << std::string(key) << YAML::Value << YAML::DoubleQuoted << v;
}

void file(YAML::Emitter& out, std::string_view key, const std::filesystem::path& path) {
  text(out, key, asset_path_text(path));
}

template <typename Vector>
void vector(YAML::Emitter& out, std::string_view key, const Vector& v) {
  out << YAML::Key << std::string(key) << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (int i = 0; i < v.size(); ++i) out << yaml::format_number(v[i]);
  out << YAML::EndSeq;
}

void matrix(YAML::Emitter& out, std::string_view key, const Eigen::Matrix3d& m) {
  out << YAML::Key << std::string(key) << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (int r = 0; r < 3; ++r) {
    out << YAML::Flow << YAML::BeginSeq;
    for (int c = 0; c < 3; ++c) out << yaml::format_number(m(r, c));
    out << YAML::EndSeq;
  }
  out << YAML::EndSeq;
}

void write_room(YAML::Emitter& out, const Room& room) {
  out << YAML::Key << "room" << YAML::Value << YAML::BeginMap;
  vector(out, "size", room.size);
  vector(out, "floor_color", room.floor_color);
  vector(out, "wall_color", room.wall_color);
  if (!room.floor_texture.empty()) file(out, "floor_texture", room.floor_texture);
  if (!room.wall_texture.empty()) file(out, "wall_texture", room.wall_texture);
  out << YAML::EndMap;
}

void write_occluder(YAML::Emitter& out, const Occluder& o) {
  out << YAML::BeginMap;
  out << YAML::Key << "type" << YAML::Value << std::string(scene_names::occluder_kind(o.kind));
  text(out, "name", o.name);
  vector(out, "position", o.position);
  switch (o.kind) {
    case Occluder::Kind::box:
      vector(out, "size", o.size);
      break;
    case Occluder::Kind::cylinder:
      number(out, "diameter", o.size.x());
      number(out, "height", o.size.y());
      break;
    case Occluder::Kind::mesh:
      file(out, "mesh", o.mesh);
      number(out, "scale", o.mesh_scale);
      break;
  }
  number(out, "yaw_deg", o.yaw_rad * kRadToDeg);
  vector(out, "color", o.color);
  out << YAML::EndMap;
}

void write_light(YAML::Emitter& out, const Light& light) {
  out << YAML::BeginMap;
  out << YAML::Key << "type" << YAML::Value << std::string(scene_names::light_kind(light.kind));
  if (light.kind == Light::Kind::directional) {
    vector(out, "direction", light.direction);
  } else {
    vector(out, "position", light.position);
  }
  number(out, "intensity", light.intensity);
  out << YAML::Key << "shadows" << YAML::Value << light.shadows;
  write_light_keyframes(out, light);
  out << YAML::EndMap;
}

void write_camera(YAML::Emitter& out, const Camera& cam) {
  out << YAML::BeginMap;
  text(out, "name", cam.name);
  out << YAML::Key << "resolution" << YAML::Value << YAML::Flow << YAML::BeginSeq << cam.width
      << cam.height << YAML::EndSeq;
  matrix(out, "K", cam.K);
  vector(out, "distortion", cam.dist);
  matrix(out, "R", cam.R);
  vector(out, "t", cam.t);
  out << YAML::EndMap;
}

// The keys of the action kind `p.kind` (read_action_keys in scene_loader.cpp).
void write_action_keys(YAML::Emitter& out, const ProceduralSpec& p) {
  const auto count = [&](int v) { out << YAML::Key << "count" << YAML::Value << v; };
  const std::string& k = p.kind;
  if (k == "jumps") {
    count(p.jumps.count);
    number(out, "distance", p.jumps.distance_m);
    number(out, "height", p.jumps.height_m);
  } else if (k == "turnaround") {
    number(out, "distance", p.turnaround.distance_m);
  } else if (k == "squat") {
    count(p.squat.count);
    number(out, "depth", p.squat.depth);
  } else if (k == "arms_cross") {
    count(p.arms_cross.count);
  } else if (k == "side_steps") {
    count(p.side_steps.count);
    number(out, "distance", p.side_steps.distance_m);
  } else if (k == "bend_forward") {
    count(p.bend_forward.count);
  } else if (k == "kick") {
    count(p.kick.count);
    number(out, "height", p.kick.height);
  } else if (k == "arm_swings") {
    number(out, "frequency", p.arm_swings.frequency_hz);
    number(out, "amplitude", p.arm_swings.amplitude_deg);
  }
}

void write_motion(YAML::Emitter& out, const MotionSource& m) {
  out << YAML::Key << "motion" << YAML::Value << YAML::BeginMap;
  if (!m.amc.empty()) {
    file(out, "amc", m.amc);
    file(out, "asf", m.asf);
    number(out, "fps", m.amc_fps);
    if (m.bvh_metres_per_unit > 0) {
      number(out, "units", m.bvh_metres_per_unit);
    } else {
      out << YAML::Key << "units" << YAML::Value << "auto";
    }
  } else if (!m.bvh.empty()) {
    file(out, "bvh", m.bvh);
    if (m.bvh_metres_per_unit > 0) {
      number(out, "units", m.bvh_metres_per_unit);
    } else {
      out << YAML::Key << "units" << YAML::Value << "auto";
    }
  } else {
    out << YAML::Key << "procedural" << YAML::Value << m.procedural.kind;
    number(out, "duration", m.procedural.duration_s);
    number(out, "speed", m.procedural.speed_m_s);
    number(out, "radius", m.procedural.path_radius);
    number(out, "turn_deg", m.procedural.turn_degrees);
    write_action_keys(out, m.procedural);
    if (m.procedural.kind == "gestures") {
      const GestureSpec& g = m.procedural.gestures;
      out << YAML::Key << "gestures" << YAML::Value << YAML::Flow << YAML::BeginSeq;
      for (const std::string& name : g.gestures.empty() ? gesture_kinds() : g.gestures) out << name;
      out << YAML::EndSeq;
      out << YAML::Key << "repetitions" << YAML::Value << std::to_string(g.repetitions);
      out << YAML::Key << "seed" << YAML::Value << std::to_string(g.seed);
      out << YAML::Key << "gesture_speed" << YAML::Value << YAML::Flow << YAML::BeginSeq
          << yaml::format_number(g.min_speed) << yaml::format_number(g.max_speed) << YAML::EndSeq;
      out << YAML::Key << "gesture_size" << YAML::Value << YAML::Flow << YAML::BeginSeq
          << yaml::format_number(g.min_size) << yaml::format_number(g.max_size) << YAML::EndSeq;
      number(out, "transition_speed", g.transition_speed);
    } else if (m.procedural.kind == "arm_gesture") {
      out << YAML::Key << "gesture" << YAML::Value << m.procedural.gesture;
    }
  }
  out << YAML::EndMap;
}

void write_actor(YAML::Emitter& out, const Actor& a) {
  out << YAML::BeginMap;
  text(out, "name", a.name);
  if (a.body.format == BodyFormat::x3d) {
    out << YAML::Key << "body" << YAML::Value << YAML::BeginMap;
    file(out, "x3d", a.body.file);
    out << YAML::EndMap;
  } else if (a.body.format == BodyFormat::mesh) {
    out << YAML::Key << "body" << YAML::Value << YAML::BeginMap;
    file(out, "mesh", a.body.file);
    text(out, "joint_map", std::string(name_of(kJointNamings, a.body.rigged.naming)));
    if (a.body.rigged.metres_per_unit > 0) {
      number(out, "units", a.body.rigged.metres_per_unit);
    } else {
      out << YAML::Key << "units" << YAML::Value << "auto";
    }
    out << YAML::EndMap;
  } else {
    number(out, "height", a.body.parameters.height);
    number(out, "girth", a.body.shape.girth);
    if (a.vary.height > 0 || a.vary.proportions > 0) {
      out << YAML::Key << "vary" << YAML::Value << YAML::BeginMap;
      number(out, "height", a.vary.height);
      number(out, "proportions", a.vary.proportions);
      out << YAML::EndMap;
    }
    out << YAML::Key << "proportions" << YAML::Value << YAML::BeginMap;
    for (const auto& [key, member] : scene_names::kProportions) {
      number(out, key, a.body.parameters.proportions.*member);
    }
    number(out, "shoulder_rise", a.body.parameters.proportions.shoulder_rise);
    out << YAML::EndMap;
  }
  out << YAML::Key << "colors" << YAML::Value << YAML::BeginMap;
  for (int r = 0; r < kMaterialRegionCount; ++r) vector(out, scene_names::kRegions[r], a.colors[r]);
  out << YAML::EndMap;
  write_motion(out, a.motion);
  if (!a.limits.empty()) file(out, "limits", a.limits);
  vector(out, "offset", a.offset);
  number(out, "yaw_deg", a.yaw_rad * kRadToDeg);
  number(out, "time_offset", a.time_offset_s);
  out << YAML::EndMap;
}

// An empty list is written as [] so that it reads back as a list, not as nothing.
template <typename T, typename WriteItem>
void list(YAML::Emitter& out, std::string_view key, const std::vector<T>& items,
          WriteItem write_item) {
  out << YAML::Key << std::string(key) << YAML::Value;
  if (items.empty()) {
    out << YAML::Flow << YAML::BeginSeq << YAML::EndSeq;
    return;
  }
  out << YAML::BeginSeq;
  for (const T& item : items) write_item(out, item);
  out << YAML::EndSeq;
}

}  // namespace

std::string scene_to_yaml(const Scene& scene) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  write_room(out, scene.room);
  list(out, "occluders", scene.occluders, write_occluder);
  list(out, "lights", scene.lights, write_light);
  number(out, "ambient", scene.ambient);
  out << YAML::Key << "rig" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "type" << YAML::Value << "explicit";
  list(out, "cameras", scene.cameras, write_camera);
  write_capture_keys(out, scene);
  out << YAML::EndMap;
  list(out, "actors", scene.actors, write_actor);

  const RenderSettings& r = scene.render;
  out << YAML::Key << "render" << YAML::Value << YAML::BeginMap;
  number(out, "fps", r.fps);
  out << YAML::Key << "first_frame" << YAML::Value << r.first_frame;
  out << YAML::Key << "frames" << YAML::Value;
  if (r.frame_count < 0) {
    out << "all";
  } else {
    out << r.frame_count;
  }
  out << YAML::Key << "samples_per_pixel" << YAML::Value << r.samples_per_pixel;
  out << YAML::Key << "seed" << YAML::Value << std::to_string(r.seed);
  out << YAML::Key << "normals" << YAML::Value << r.normals;
  if (r.shutter > 0) number(out, "shutter", r.shutter);
  out << YAML::EndMap;

  out << YAML::Key << "noise" << YAML::Value << YAML::BeginMap;
  number(out, "rgb_sigma", scene.noise.rgb_sigma);
  number(out, "depth_sigma", scene.noise.depth_sigma_m);
  out << YAML::EndMap;
  out << YAML::EndMap;
  return "# simcap scene, resolved: every default filled in, cameras as an explicit rig.\n" +
         std::string(out.c_str()) + "\n";
}

}  // namespace simcap
