#include <yaml-cpp/yaml.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/limits.h"
#include "core/rig.h"
#include "models/humanoid.h"
#include "models/procedural_actions.h"
#include "models/shipped_assets.h"
#include "models/urdf_io.h"
#include "scenes/camera_jitter.h"
#include "scenes/capture_keys.h"
#include "scenes/scene.h"
#include "scenes/scene_names.h"
#include "scenes/yaml_field.h"
#include "scenes/yaml_overrides.h"

namespace simcap {

namespace {
using yaml::Field;
using yaml::Map;

constexpr double kDegToRad = std::numbers::pi / 180.0;
// A subject's standing height, m (within what build_humanoid builds).
constexpr double kMinHeight = 0.5;
constexpr double kMaxHeight = 2.5;

// 'auto' (0) or metres per file unit.
double read_units(const Field& v) {
  if (v.is_scalar() && v.node().Scalar() == "auto") return 0.0;
  if (!v.is_scalar()) v.expected("'auto' or metres per file unit (a number > 0)");
  return v.number(yaml::positive(1000));
}

template <std::size_t N>
int read_word(const Field& f, const std::array<std::string_view, N>& words) {
  const std::string what = "one of " + scene_names::one_of(words);
  if (!f.is_scalar()) f.expected(what);
  for (std::size_t i = 0; i < N; ++i) {
    if (f.node().Scalar() == words[i]) return static_cast<int>(i);
  }
  f.expected(what);
}

Rgb read_color(const Field& f) {
  const char* what =
      "a colour: [r, g, b] with each in [0, 1], or \"#rrggbb\" in quotes (unquoted, # starts a "
      "YAML comment)";
  if (f.is_sequence()) {
    const auto c = f.items(3, 3);
    return {c[0].number_f(yaml::closed(0, 1)), c[1].number_f(yaml::closed(0, 1)),
            c[2].number_f(yaml::closed(0, 1))};
  }
  if (!f.is_scalar()) f.expected(what);
  const std::string& s = f.node().Scalar();
  if (s.size() != 7 || s[0] != '#' ||
      !std::all_of(s.begin() + 1, s.end(), [](unsigned char c) { return std::isxdigit(c) != 0; })) {
    f.expected(what);
  }
  Rgb rgb;
  for (int i = 0; i < 3; ++i) rgb[i] = std::stoi(s.substr(1 + 2 * i, 2), nullptr, 16) / 255.0f;
  return rgb;
}

class SceneReader {
 public:
  explicit SceneReader(std::filesystem::path scene_dir) : scene_dir_(std::move(scene_dir)) {}

  Scene read(const Field& top);

 private:
  std::filesystem::path read_file(const Field& f) const;
  Room read_room(const Field& f) const;
  Occluder read_occluder(const Field& f, int index) const;
  Light read_light(const Field& f) const;
  // The cameras, and the rig's capture keys into `scene`.
  std::vector<Camera> read_rig(const Field& f, Scene& scene) const;
  Actor read_actor(const Field& f, int index) const;
  void read_body_file(const Field& f, BodySource& body) const;
  MotionSource read_motion(const Field& f) const;
  RenderSettings read_render(const Field& f) const;
  SensorNoise read_noise(const Field& f) const;

  std::filesystem::path scene_dir_;
};

std::filesystem::path SceneReader::read_file(const Field& f) const {
  const std::filesystem::path path = resolve_asset_path(f.text(), scene_dir_);
  if (!std::filesystem::is_regular_file(path)) {
    f.fail("expected an existing file; '" + path.string() + "' does not exist (relative paths " +
           "start at the scene file's folder, 'asset:' paths at " + asset_dir().string() + ")");
  }
  return path;
}

Room SceneReader::read_room(const Field& f) const {
  Map m(f);
  Room room;
  if (auto v = m.take("size")) room.size = v->vector3(yaml::positive(1000));
  if (auto v = m.take("floor_color")) room.floor_color = read_color(*v);
  if (auto v = m.take("wall_color")) room.wall_color = read_color(*v);
  if (auto v = m.take("floor_texture")) room.floor_texture = read_file(*v);
  if (auto v = m.take("wall_texture")) room.wall_texture = read_file(*v);
  m.finish();
  return room;
}

Occluder SceneReader::read_occluder(const Field& f, int index) const {
  Map m(f);
  Occluder o;
  o.kind = static_cast<Occluder::Kind>(read_word(m.require("type"), scene_names::kOccluderKinds));
  o.name = "occluder" + std::to_string(index);
  if (auto v = m.take("name")) o.name = v->text();
  if (auto v = m.take("position")) o.position = v->vector3(yaml::any_finite());
  if (auto v = m.take("yaw_deg")) o.yaw_rad = v->number(yaml::any_finite()) * kDegToRad;
  if (auto v = m.take("color")) o.color = read_color(*v);
  switch (o.kind) {
    case Occluder::Kind::box:
      if (auto v = m.take("size")) o.size = v->vector3(yaml::positive(1000));
      break;
    case Occluder::Kind::cylinder:
      // The cylinder's footprint is round: size holds (diameter, height, diameter).
      if (auto v = m.take("diameter")) o.size.x() = o.size.z() = v->number(yaml::positive(1000));
      if (auto v = m.take("height")) o.size.y() = v->number(yaml::positive(1000));
      break;
    case Occluder::Kind::mesh:
      o.mesh = read_file(m.require("mesh"));
      if (auto v = m.take("scale")) o.mesh_scale = v->number(yaml::positive(1000));
      break;
  }
  m.finish();
  return o;
}

Light SceneReader::read_light(const Field& f) const {
  Map m(f);
  Light light;
  light.kind = static_cast<Light::Kind>(read_word(m.require("type"), scene_names::kLightKinds));
  if (light.kind == Light::Kind::directional) {
    if (auto v = m.take("direction")) {
      const Eigen::Vector3d d = v->vector3(yaml::any_finite());
      if (d.norm() < 1e-9) v->fail("expected a non-zero direction");
      light.direction = d;
    }
    light.direction.normalize();
  } else if (auto v = m.take("position")) {
    light.position = v->vector3(yaml::any_finite());
  }
  if (auto v = m.take("intensity")) light.intensity = v->number(yaml::non_negative(1000));
  if (auto v = m.take("shadows")) light.shadows = v->boolean();
  if (auto v = m.take("keyframes")) light.keyframes = read_light_keyframes(*v, light.kind);
  m.finish();
  return light;
}

// Image size, intrinsics and distortion of a camera; a rig's values are the defaults of its
// explicit cameras.
struct Intrinsics {
  int width = 640;
  int height = 480;
  double hfov_rad = ImageSpec{}.hfov_rad;
  std::optional<Eigen::Matrix3d> K;  // when set, replaces the K that hfov_rad gives
  Distortion dist = Distortion::Zero();

  // Sets the image size, distortion and, when given as such, K; a camera built by look_at()
  // from hfov_rad already has the K that the field of view gives.
  void apply(Camera& cam) const {
    cam.width = width;
    cam.height = height;
    cam.dist = dist;
    if (K) cam.K = *K;
  }
};

Intrinsics read_intrinsics(Map& m, const Intrinsics& inherited) {
  Intrinsics in = inherited;
  if (auto v = m.take("resolution")) {
    const auto wh = v->items(2, 2);
    in.width = wh[0].integer(1, limits::kMaxImageSide, "simcap's largest image side");
    in.height = wh[1].integer(1, limits::kMaxImageSide, "simcap's largest image side");
    if (static_cast<long>(in.width) * in.height > limits::kMaxImagePixels) {
      v->fail(std::to_string(in.width) + "x" + std::to_string(in.height) +
              " pixels is more than the " + std::to_string(limits::kMaxImagePixels) + " (" +
              limits::kMaxImagePixelsText + ") simcap allows an image");
    }
  }
  auto hfov = m.take("hfov_deg");
  auto fx = m.take("fx");
  auto fy = m.take("fy");
  auto cx = m.take("cx");
  auto cy = m.take("cy");
  auto K = m.take("K");
  const int ways = (hfov ? 1 : 0) + (fx || fy || cx || cy ? 1 : 0) + (K ? 1 : 0);
  if (ways > 1) {
    const Field& second = K ? *K : (fx ? *fx : fy ? *fy : cx ? *cx : *cy);
    second.fail(
        "give the focal length one way only: hfov_deg, or fx and fy (with optional cx, "
        "cy), or K");
  }
  if (hfov) {
    in.hfov_rad = hfov->number({0, 180, false, false}) * kDegToRad;
    in.K.reset();
  } else if (fx || fy || cx || cy) {
    if (!fx || !fy) (fx ? *fx : fy ? *fy : cx ? *cx : *cy).fail("fx and fy must be given together");
    Eigen::Matrix3d k = Eigen::Matrix3d::Identity();
    k(0, 0) = fx->number(yaml::positive(1e5));
    k(1, 1) = fy->number(yaml::positive(1e5));
    k(0, 2) = cx ? cx->number(yaml::any_finite()) : 0.5 * (in.width - 1);
    k(1, 2) = cy ? cy->number(yaml::any_finite()) : 0.5 * (in.height - 1);
    in.K = k;
  } else if (K) {
    const Eigen::Matrix3d k = K->matrix(3, 3);
    if (k(0, 1) != 0 || k(1, 0) != 0 || k(2, 0) != 0 || k(2, 1) != 0 || k(2, 2) != 1 ||
        k(0, 0) <= 0 || k(1, 1) <= 0) {
      K->fail("expected [[fx, 0, cx], [0, fy, cy], [0, 0, 1]] with fx, fy > 0");
    }
    in.K = k;
  }
  if (auto v = m.take("distortion")) {
    const auto d = v->items(5, 5);
    for (int i = 0; i < 5; ++i) in.dist[i] = d[i].number(yaml::any_finite());
  }
  return in;
}

void check_inside_room(const Field& f, const Camera& cam, const Room& room) {
  const Eigen::Vector3d c = cam.centre();
  const Eigen::Vector3d half = 0.5 * room.size;
  if (std::abs(c.x()) < half.x() && c.y() > 0 && c.y() < room.size.y() &&
      std::abs(c.z()) < half.z()) {
    return;
  }
  f.fail("camera " + cam.name + " at (" + yaml::format_number(c.x()) + ", " +
         yaml::format_number(c.y()) + ", " + yaml::format_number(c.z()) +
         ") is outside the room (x and z within +-half the room size, y in (0, room height))");
}

CameraJitter read_camera_jitter(const Field& f) {
  Map m(f);
  CameraJitter j;
  if (auto v = m.take("position_m")) j.position_m = v->number(yaml::non_negative(10));
  if (auto v = m.take("rotation_deg")) j.rotation_deg = v->number(yaml::closed(0, 180));
  if (auto v = m.take("seed")) j.seed = v->unsigned64();
  m.finish();
  return j;
}

Camera read_explicit_camera(const Field& f, int index, const Intrinsics& rig_intrinsics) {
  Map m(f);
  std::string name = camera_name(index);
  if (auto v = m.take("name")) name = v->text();
  const Intrinsics in = read_intrinsics(m, rig_intrinsics);
  auto eye = m.take("eye");
  auto target = m.take("target");
  auto up = m.take("up");
  auto R = m.take("R");
  auto t = m.take("t");
  Camera cam;
  if ((eye || target || up) && (R || t)) {
    (R ? *R : *t).fail("give the pose one way only: eye and target (optional up), or R and t");
  }
  if (eye || target || up) {
    if (!eye || !target) f.fail("an eye-and-target camera needs both 'eye' and 'target'");
    const Eigen::Vector3d e = eye->vector3(yaml::any_finite());
    const Eigen::Vector3d tg = target->vector3(yaml::any_finite());
    const Eigen::Vector3d u = up ? up->vector3(yaml::any_finite()) : Eigen::Vector3d::UnitY();
    if ((tg - e).norm() < 1e-9) target->fail("the target must differ from the eye");
    try {
      cam = Camera::look_at(name, in.width, in.height, in.hfov_rad, e, tg, u);
    } catch (const Error& err) {
      (up ? *up : *target).fail(err.what());
    }
  } else if (R && t) {
    cam.name = name;
    const Eigen::Matrix3d r = R->matrix(3, 3);
    if ((r * r.transpose() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-6 ||
        r.determinant() < 0) {
      R->fail("expected a rotation matrix (orthonormal rows, determinant +1, to 1e-6)");
    }
    cam.R = r;
    cam.t = t->vector3(yaml::any_finite());
    if (!in.K) {
      // K from the field of view exactly as look_at() builds it for the other cameras.
      const double f = 0.5 * in.width / std::tan(0.5 * in.hfov_rad);
      cam.K << f, 0, 0.5 * (in.width - 1), 0, f, 0.5 * (in.height - 1), 0, 0, 1;
    }
  } else {
    f.fail("a camera needs a pose: 'eye' and 'target' (optional 'up'), or 'R' and 't'");
  }
  in.apply(cam);
  m.finish();
  return cam;
}

std::vector<Camera> SceneReader::read_rig(const Field& f, Scene& scene) const {
  const Room& room = scene.room;
  Map m(f);
  enum RigType { corners, ring, explicit_list };
  static constexpr std::array<std::string_view, 3> kTypes = {"corners", "ring", "explicit"};
  const RigType type =
      m.has("type") ? static_cast<RigType>(read_word(*m.take("type"), kTypes)) : corners;
  const Intrinsics in = read_intrinsics(m, Intrinsics{});
  std::vector<Camera> cams;
  if (type == explicit_list) {
    const auto list = m.require("cameras").items(1, 1000);
    for (std::size_t i = 0; i < list.size(); ++i) {
      cams.push_back(read_explicit_camera(list[i], static_cast<int>(i), in));
      check_inside_room(list[i], cams.back(), room);
      for (std::size_t j = 0; j < i; ++j) {
        if (cams[j].name == cams[i].name) list[i].fail("duplicate camera name " + cams[i].name);
      }
    }
  } else {
    Eigen::Vector3d target(0.0, 1.0, 0.0);
    if (auto v = m.take("target")) target = v->vector3(yaml::any_finite());
    const ImageSpec spec{in.width, in.height, in.hfov_rad};
    double height = 2.5;
    const auto height_field = m.take("height");
    if (height_field) height = height_field->number(yaml::any_finite());
    std::optional<Field> radius_field;
    if (type == ring) {
      int count = 8;
      double radius = 3.0;
      if (auto v = m.take("count")) count = v->integer(1, 1000);
      radius_field = m.take("radius");
      if (radius_field) radius = radius_field->number(yaml::positive(1000));
      cams = ring_rig(count, target, radius, height, spec);
    } else {
      double inset = 0.1;
      if (auto v = m.take("count"); v && v->integer(1, 1000) != 4) {
        v->fail("a corners rig has exactly 4 cameras (use type: ring or explicit for others)");
      }
      auto inset_field = m.take("inset");
      // Zero would put the cameras on the walls, where no camera centre may be.
      if (inset_field) inset = inset_field->number(yaml::positive(1000));
      if (2 * inset >= std::min(room.size.x(), room.size.z())) {
        (inset_field ? *inset_field : f).fail("the inset must be less than half the room size");
      }
      cams = corner_rig(room.size.x(), room.size.z(), height, inset, target, spec);
    }
    for (Camera& cam : cams) {
      in.apply(cam);
      // Blame the key that put the camera outside: its height, or the ring's radius.
      const double y = cam.centre().y();
      const auto& culprit = y <= 0 || y >= room.size.y() ? height_field : radius_field;
      check_inside_room(culprit ? *culprit : f, cam, room);
    }
  }
  if (auto v = m.take("jitter")) {
    const CameraJitter jitter = read_camera_jitter(*v);
    // Refused when any draw could leave the room, so that no seed makes the scene invalid.
    const Eigen::Vector3d half = 0.5 * room.size;
    const double p = jitter.position_m;
    for (Camera& cam : cams) {
      const Eigen::Vector3d c = cam.centre();
      if (std::abs(c.x()) + p >= half.x() || c.y() - p <= 0 || c.y() + p >= room.size.y() ||
          std::abs(c.z()) + p >= half.z()) {
        v->fail("position_m " + yaml::format_number(p) + " could move camera " + cam.name +
                " at (" + yaml::format_number(c.x()) + ", " + yaml::format_number(c.y()) + ", " +
                yaml::format_number(c.z()) + ") outside the room");
      }
      cam = jittered(cam, jitter);
    }
  }
  read_capture_keys(m, cams, scene);
  m.finish();
  return cams;
}

// The keys of the action `p.kind` (its own, in scenes/README.md), read with `take`; their ranges
// and how they fit the duration are checked by procedural::parameter_problem.
template <class Take>
void read_action_keys(ProceduralSpec& p, const Take& take) {
  const auto count = [&](int* out) {
    if (auto v = take("count")) *out = v->integer(-1000000, 1000000);
  };
  const auto number = [&](const char* key, double* out) {
    if (auto v = take(key)) *out = v->number(yaml::any_finite());
  };
  const std::string& k = p.kind;
  if (k == "jumps") {
    count(&p.jumps.count);
    number("distance", &p.jumps.distance_m);
    number("height", &p.jumps.height_m);
  } else if (k == "turnaround") {
    number("distance", &p.turnaround.distance_m);
  } else if (k == "squat") {
    count(&p.squat.count);
    number("depth", &p.squat.depth);
  } else if (k == "arms_cross") {
    count(&p.arms_cross.count);
  } else if (k == "side_steps") {
    count(&p.side_steps.count);
    number("distance", &p.side_steps.distance_m);
  } else if (k == "bend_forward") {
    count(&p.bend_forward.count);
  } else if (k == "kick") {
    count(&p.kick.count);
    number("height", &p.kick.height);
  } else if (k == "arm_swings") {
    number("frequency", &p.arm_swings.frequency_hz);
    number("amplitude", &p.arm_swings.amplitude_deg);
  }
}

namespace {

// The keys of a gesture corpus (models/gesture_motion.h), known only for `procedural: gestures`.
void read_gestures(Map& m, GestureSpec& g) {
  g.seed = 0;  // the render seed (resolve_seeded_choices)
  if (auto v = m.take("gestures")) {
    g.gestures.clear();
    for (const Field& item : v->items(1, 1000)) {
      const std::string name = item.text();
      const auto& known = gesture_kinds();
      if (std::find(known.begin(), known.end(), name) == known.end()) {
        item.expected("one of " + scene_names::one_of(known));
      }
      g.gestures.push_back(name);
    }
  }
  if (auto v = m.take("repetitions")) g.repetitions = v->integer(1, 1000);
  if (auto v = m.take("seed")) g.seed = v->unsigned64();
  auto range = [&](const char* key, double& lo, double& hi, double most) {
    if (auto v = m.take(key)) {
      const auto items = v->items(2, 2);
      lo = items[0].number(yaml::positive(most));
      hi = items[1].number(yaml::positive(most));
      if (hi < lo) items[1].expected("a number >= the first (" + yaml::format_number(lo) + ")");
    }
  };
  range("gesture_speed", g.min_speed, g.max_speed, 10);
  range("gesture_size", g.min_size, g.max_size, 2);
  if (auto v = m.take("transition_speed")) g.transition_speed = v->number(yaml::positive(10));
}

}  // namespace

MotionSource SceneReader::read_motion(const Field& f) const {
  Map m(f);
  MotionSource src;
  const bool bvh = m.has("bvh");
  const bool amc = m.has("amc");
  const bool procedural = m.has("procedural");
  if (bvh + amc + procedural != 1) {
    f.fail(
        "a motion needs exactly one of 'bvh' (a motion-capture file), 'amc' (with 'asf', "
        "CMU's Acclaim files) or 'procedural' (one of " +
        scene_names::one_of(procedural_kinds()) + ")");
  }
  if (amc) {
    src.amc = read_file(*m.take("amc"));
    src.asf = read_file(m.require("asf"));
    if (auto v = m.take("fps")) src.amc_fps = v->number(yaml::positive(10000));
    if (auto v = m.take("units")) {
      src.bvh_metres_per_unit = read_units(*v);
    }
  } else if (bvh) {
    src.bvh = read_file(*m.take("bvh"));
    if (auto v = m.take("units")) {
      src.bvh_metres_per_unit = read_units(*v);
    }
  } else {
    const Field kind = *m.take("procedural");
    const auto& kinds = procedural_kinds();
    if (!kind.is_scalar() ||
        std::find(kinds.begin(), kinds.end(), kind.node().Scalar()) == kinds.end()) {
      kind.expected("one of " + scene_names::one_of(procedural_kinds()));
    }
    src.procedural.kind = kind.node().Scalar();
    // Keys an action's checks may blame (models/procedural_actions.h).
    std::map<std::string, Field, std::less<>> given;
    const auto take = [&](const char* key) {
      auto v = m.take(key);
      if (v) given.emplace(key, *v);
      return v;
    };
    ProceduralSpec& p = src.procedural;
    if (auto v = take("duration")) p.duration_s = v->number(yaml::positive(3600));
    if (auto v = take("speed")) p.speed_m_s = v->number(yaml::positive(20));
    if (auto v = m.take("radius")) p.path_radius = v->number(yaml::positive(100));
    if (auto v = m.take("turn_deg")) p.turn_degrees = v->number(yaml::closed(-3600, 3600));
    read_action_keys(p, take);
    if (p.kind == "gestures") read_gestures(m, p.gestures);
    if (const auto problem = procedural::parameter_problem(p)) {
      const auto at = given.find(problem->key);
      (at != given.end() ? at->second : f)
          .fail((at != given.end() ? "" : "the default " + problem->key + " of " + p.kind + " ") +
                problem->message);
    }
    if (p.kind == "arm_gesture") {
      if (auto v = m.take("gesture")) {
        const auto& names = gesture_names();
        if (!v->is_scalar() ||
            std::find(names.begin(), names.end(), v->node().Scalar()) == names.end()) {
          v->expected("one of " + scene_names::one_of(names));
        }
        p.gesture = v->node().Scalar();
      }
    }
  }
  m.finish();
  return src;
}

void SceneReader::read_body_file(const Field& f, BodySource& body) const {
  Map m(f);
  if (m.has("x3d") == m.has("mesh")) {
    f.expected("a map with one of 'x3d: <an H-Anim X3D file>' or 'mesh: <a rigged mesh>'");
  }
  if (auto v = m.take("x3d")) {
    body.format = BodyFormat::x3d;
    body.file = read_file(*v);
  } else {
    body.format = BodyFormat::mesh;
    body.file = read_file(*m.take("mesh"));
    if (auto v = m.take("joint_map")) {
      const auto& names = kJointNamings;
      const auto it = std::find_if(names.begin(), names.end(), [&](const auto& n) {
        return v->is_scalar() && n.first == v->node().Scalar();
      });
      if (it == names.end()) v->expected("one of " + choices_text(kJointNamings));
      body.rigged.naming = it->second;
    }
    if (auto v = m.take("units")) {
      body.rigged.metres_per_unit = read_units(*v);
    }
  }
  m.finish();
}

Actor SceneReader::read_actor(const Field& f, int index) const {
  Map m(f);
  Actor a;
  a.name = "actor" + std::to_string(index);
  if (auto v = m.take("name")) a.name = v->text();
  if (auto v = m.take("body")) {
    read_body_file(*v, a.body);
    for (const char* key : {"height", "girth", "proportions", "vary"}) {
      if (auto x = m.take(key)) {
        x->fail("the body comes from a file (" + v->path() + "); height, girth, proportions and " +
                "vary shape simcap's own humanoid only");
      }
    }
  }
  BodyParameters& body = a.body.parameters;
  if (auto v = m.take("height")) body.height = v->number(yaml::closed(kMinHeight, kMaxHeight));
  if (auto v = m.take("girth")) a.body.shape.girth = v->number(yaml::closed(0.5, 2.0));
  const std::optional<Field> vary = m.take("vary");
  std::optional<Field> vary_height, vary_proportions;
  if (vary) {
    Map p(*vary);
    vary_height = p.take("height");
    if (vary_height) a.vary.height = vary_height->number(yaml::closed(0.0, 0.5));
    vary_proportions = p.take("proportions");
    if (vary_proportions) a.vary.proportions = vary_proportions->number(yaml::closed(0.0, 0.1));
    p.finish();
  }
  if (auto v = m.take("proportions")) {
    Map p(*v);
    for (const auto& [key, member] : scene_names::kProportions) {
      if (auto x = p.take(key)) body.proportions.*member = x->number(yaml::positive(1.0));
    }
    if (auto x = p.take("shoulder_rise")) {
      body.proportions.shoulder_rise = x->number(yaml::closed(-0.05, 0.05));
    }
    p.finish();
    try {
      check_proportions(body.proportions);
    } catch (const Error& e) {
      v->fail(e.what());
    }
  }
  // Every subject a seed can draw (seeded_choices.cpp) must be a body simcap builds.
  if (vary_height &&
      (body.height - a.vary.height < kMinHeight || body.height + a.vary.height > kMaxHeight)) {
    vary_height->fail("height " + yaml::format_number(body.height) + " +- " +
                      yaml::format_number(a.vary.height) + " m leaves [" +
                      yaml::format_number(kMinHeight) + ", " + yaml::format_number(kMaxHeight) +
                      "] m, the heights a subject may have");
  }
  if (vary_proportions) {
    for (const double leg : {1.0 - a.vary.proportions, 1.0 + a.vary.proportions}) {
      BodyProportions p = body.proportions;
      p.hip_height *= leg;
      p.knee_height *= leg;
      try {
        check_proportions(p);
      } catch (const Error& e) {
        vary_proportions->fail(std::string(e.what()) + " with the legs " +
                               yaml::format_number(leg) + " times as long");
      }
    }
  }
  if (auto v = m.take("colors")) {
    Map c(*v);
    for (int r = 0; r < kMaterialRegionCount; ++r) {
      if (auto x = c.take(scene_names::kRegions[r])) a.colors[r] = read_color(*x);
    }
    c.finish();
  }
  a.motion = read_motion(m.require("motion"));
  if (auto v = m.take("limits")) {
    a.limits = read_file(*v);
    try {
      read_urdf_limits(a.limits, build_humanoid());
    } catch (const Error& e) {
      v->fail(e.what());
    }
  }
  if (auto v = m.take("offset")) a.offset = v->vector3(yaml::any_finite());
  if (auto v = m.take("yaw_deg")) a.yaw_rad = v->number(yaml::any_finite()) * kDegToRad;
  if (auto v = m.take("time_offset")) a.time_offset_s = v->number(yaml::any_finite());
  m.finish();
  return a;
}

RenderSettings SceneReader::read_render(const Field& f) const {
  Map m(f);
  RenderSettings r;
  if (auto v = m.take("fps")) r.fps = v->number(yaml::positive(1000));
  if (auto v = m.take("first_frame")) {
    r.first_frame = v->integer(0, limits::kMaxFrames, "simcap's largest frame count");
  }
  if (auto v = m.take("frames")) {
    if (v->is_scalar() && v->node().Scalar() == "all") {
      r.frame_count = -1;
    } else {
      if (!v->is_scalar()) v->expected("'all' or a frame count (an integer >= 1)");
      r.frame_count = v->integer(1, limits::kMaxFrames, "simcap's largest frame count");
    }
  }
  if (auto v = m.take("samples_per_pixel")) r.samples_per_pixel = v->integer(1, 65536);
  if (auto v = m.take("seed")) r.seed = v->unsigned64();
  if (auto v = m.take("normals")) r.normals = v->boolean();
  if (auto v = m.take("shutter")) {
    r.shutter = v->number(yaml::closed(0, 1));
    // One sample per pixel cannot spread over an exposure: say so rather than render it sharp.
    if (r.shutter > 0 && r.samples_per_pixel == 1) {
      v->fail(
          "motion blur needs render.samples_per_pixel > 1 (each sample is a time in the "
          "exposure)");
    }
  }
  m.finish();
  return r;
}

SensorNoise SceneReader::read_noise(const Field& f) const {
  Map m(f);
  SensorNoise n;
  if (auto v = m.take("rgb_sigma")) n.rgb_sigma = v->number(yaml::non_negative(255));
  if (auto v = m.take("depth_sigma")) n.depth_sigma_m = v->number(yaml::non_negative(10));
  m.finish();
  return n;
}

template <typename T>
void check_unique_names(const std::vector<Field>& items, const std::vector<T>& values,
                        std::string_view what) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (values[i].name == values[j].name) {
        items[i].fail("duplicate " + std::string(what) + " name " + values[i].name);
      }
    }
  }
}

// The value of `key`, or an empty section at that path when the file leaves it out.
Field section(Map& m, std::string_view key) {
  if (auto v = m.take(key)) return *v;
  return m.field().child(key, YAML::Node(), m.field().node().Mark());
}

Scene SceneReader::read(const Field& top) {
  Map m(top);
  Scene scene;
  scene.room = read_room(section(m, "room"));
  if (auto v = m.take("occluders")) {
    const auto items = v->items(0, 100000);
    for (std::size_t i = 0; i < items.size(); ++i) {
      scene.occluders.push_back(read_occluder(items[i], static_cast<int>(i)));
    }
    check_unique_names(items, scene.occluders, "occluder");
  }
  if (auto v = m.take("lights")) {
    for (const Field& item : v->items(0, 64)) scene.lights.push_back(read_light(item));
  } else {
    Light light;
    light.direction.normalize();
    scene.lights.push_back(light);
  }
  if (auto v = m.take("ambient")) scene.ambient = v->number(yaml::closed(0, 1));
  scene.cameras = read_rig(section(m, "rig"), scene);
  if (auto v = m.take("actors")) {
    const auto items = v->items(0, 64);
    for (std::size_t i = 0; i < items.size(); ++i) {
      scene.actors.push_back(read_actor(items[i], static_cast<int>(i)));
    }
    check_unique_names(items, scene.actors, "actor");
  }
  const Field render = section(m, "render");
  scene.render = read_render(render);
  if (scene.actors.empty() && scene.render.frame_count < 0) {
    Map r(render);
    r.take("frames").value_or(render).fail(
        "a scene without actors needs a frame count (render.frames); 'all' means as long as "
        "the longest motion");
  }
  scene.noise = read_noise(section(m, "noise"));
  m.finish();
  return scene;
}

YAML::Node parse_yaml(const std::filesystem::path& path) {
  const std::string text = read_text(path);
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw_input_error(path, e.mark.is_null() ? 0 : e.mark.line + 1, "", "not valid YAML: " + e.msg);
  }
}

}  // namespace

Scene load_scene(const std::filesystem::path& path, const std::vector<std::string>& overrides) {
  yaml::Origin origin{std::filesystem::absolute(path).lexically_normal(), {}};
  YAML::Node root = parse_yaml(origin.file);
  yaml::apply_overrides(root, overrides, origin);
  Scene scene = SceneReader(origin.file.parent_path()).read(Field(root, "", &origin));
  scene.source = origin.file;
  return scene;
}

}  // namespace simcap
