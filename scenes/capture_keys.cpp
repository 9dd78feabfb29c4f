#include "scenes/capture_keys.h"

#include <cmath>
#include <limits>

namespace simcap {
namespace {

constexpr double kMaxMs = 10000;

void number(YAML::Emitter& out, std::string_view key, double v) {
  out << YAML::Key << std::string(key) << YAML::Value << yaml::format_number(v);
}

template <typename Vector>
void vector(YAML::Emitter& out, std::string_view key, const Vector& v) {
  out << YAML::Key << std::string(key) << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (int i = 0; i < static_cast<int>(v.size()); ++i) out << yaml::format_number(v[i]);
  out << YAML::EndSeq;
}

CalibrationError read_calibration_error(const yaml::Field& f) {
  yaml::Map m(f);
  CalibrationError e;
  if (auto v = m.take("rotation_deg")) e.rotation_deg = v->number(yaml::closed(0, 180));
  if (auto v = m.take("translation_m")) e.translation_m = v->number(yaml::non_negative(100));
  if (auto v = m.take("focal_rel")) e.focal_rel = v->number({0, 1, true, false});
  if (auto v = m.take("principal_px")) e.principal_px = v->number(yaml::non_negative(1e4));
  if (auto v = m.take("seed")) e.seed = v->unsigned64();
  m.finish();
  return e;
}

void read_sync(const yaml::Field& f, int camera_count, CaptureTiming& t) {
  yaml::Map m(f);
  auto list = m.take("offset_ms");
  auto sigma = m.take("offset_ms_sigma");
  auto seed = m.take("seed");
  if (list && (sigma || seed)) {
    (sigma ? *sigma : *seed)
        .fail(
            "give the offsets one way only: offset_ms (one per camera), or offset_ms_sigma "
            "with an optional seed");
  }
  if (list) {
    const auto items = list->items(1, 1000);
    if (static_cast<int>(items.size()) != camera_count) {
      list->fail("expected one offset per camera (" + std::to_string(camera_count) + "), got " +
                 std::to_string(items.size()));
    }
    for (const yaml::Field& item : items) {
      t.offset_ms.push_back(item.number(yaml::closed(-kMaxMs, kMaxMs)));
    }
  } else if (sigma) {
    t.offset_sigma_ms = sigma->number(yaml::non_negative(kMaxMs));
    if (seed) t.seed = seed->unsigned64();
  } else {
    f.fail("expected offset_ms (one per camera) or offset_ms_sigma");
  }
  m.finish();
}

}  // namespace

void read_capture_keys(yaml::Map& rig, const std::vector<Camera>& cameras, Scene& scene) {
  if (auto v = rig.take("calibration_error")) scene.calibration_error = read_calibration_error(*v);
  if (auto v = rig.take("sync")) read_sync(*v, static_cast<int>(cameras.size()), scene.timing);
  if (auto v = rig.take("readout_ms"))
    scene.timing.readout_ms = v->number(yaml::non_negative(kMaxMs));
  if (auto v = rig.take("auto_exposure")) scene.timing.auto_exposure = v->boolean();
}

std::vector<LightKeyframe> read_light_keyframes(const yaml::Field& f, Light::Kind kind) {
  std::vector<LightKeyframe> keys;
  for (const yaml::Field& item : f.items(1, 100000)) {
    yaml::Map m(item);
    LightKeyframe k;
    const yaml::Field time = m.require("time");
    k.time_s = time.number(yaml::any_finite());
    if (!keys.empty() && !(k.time_s > keys.back().time_s)) {
      time.fail("keyframe times must increase (the previous keyframe is at " +
                yaml::format_number(keys.back().time_s) + " s)");
    }
    if (auto v = m.take("intensity")) k.intensity = v->number(yaml::non_negative(1000));
    if (kind == Light::Kind::point) {
      if (auto v = m.take("position")) k.position = v->vector3(yaml::any_finite());
    } else if (auto v = m.take("direction")) {
      const Eigen::Vector3d d = v->vector3(yaml::any_finite());
      if (d.norm() < 1e-9) v->fail("expected a non-zero direction");
      k.direction = d;
      // Interpolation passes through zero between opposite directions.
      for (auto prev = keys.rbegin(); prev != keys.rend(); ++prev) {
        if (!prev->direction) continue;
        if (prev->direction->normalized().dot(d.normalized()) < -1 + 1e-9) {
          v->fail(
              "a direction opposite to the previous keyframe's cannot be interpolated; add a "
              "keyframe in between");
        }
        break;
      }
    }
    m.finish();
    if (!k.intensity && !k.position && !k.direction) {
      item.fail(std::string("a keyframe needs a value besides its time: intensity or ") +
                (kind == Light::Kind::point ? "position" : "direction"));
    }
    keys.push_back(k);
  }
  return keys;
}

void write_capture_keys(YAML::Emitter& out, const Scene& scene) {
  const CalibrationError& e = scene.calibration_error;
  if (e.any()) {
    out << YAML::Key << "calibration_error" << YAML::Value << YAML::BeginMap;
    number(out, "rotation_deg", e.rotation_deg);
    number(out, "translation_m", e.translation_m);
    number(out, "focal_rel", e.focal_rel);
    number(out, "principal_px", e.principal_px);
    out << YAML::Key << "seed" << YAML::Value << std::to_string(e.seed);
    out << YAML::EndMap;
  }
  const CaptureTiming& t = scene.timing;
  if (!t.synchronised()) {
    out << YAML::Key << "sync" << YAML::Value << YAML::BeginMap;
    if (!t.offset_ms.empty()) {
      vector(out, "offset_ms", t.offset_ms);
    } else {
      number(out, "offset_ms_sigma", t.offset_sigma_ms);
      out << YAML::Key << "seed" << YAML::Value << std::to_string(t.seed);
    }
    out << YAML::EndMap;
  }
  if (t.readout_ms > 0) number(out, "readout_ms", t.readout_ms);
  if (t.auto_exposure) out << YAML::Key << "auto_exposure" << YAML::Value << true;
}

void write_light_keyframes(YAML::Emitter& out, const Light& light) {
  if (light.keyframes.empty()) return;
  out << YAML::Key << "keyframes" << YAML::Value << YAML::BeginSeq;
  for (const LightKeyframe& k : light.keyframes) {
    out << YAML::Flow << YAML::BeginMap;
    number(out, "time", k.time_s);
    if (k.intensity) number(out, "intensity", *k.intensity);
    if (k.position) vector(out, "position", *k.position);
    if (k.direction) vector(out, "direction", *k.direction);
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;
}

namespace {

// The value of one keyed quantity at `t`: linear between the keyframes that give it.
template <typename T, typename Get>
std::optional<T> keyed_value(const std::vector<LightKeyframe>& keys, double t, Get get) {
  const LightKeyframe* before = nullptr;
  for (const LightKeyframe& k : keys) {
    const std::optional<T> value = get(k);
    if (!value) continue;
    if (k.time_s >= t) {
      if (!before || k.time_s == t) return value;
      const double a = (t - before->time_s) / (k.time_s - before->time_s);
      return T((1 - a) * *get(*before) + a * *value);
    }
    before = &k;
  }
  if (before) return get(*before);
  return std::nullopt;
}

}  // namespace

Light light_at(const Light& light, double time_s) {
  Light l = light;
  const auto& keys = light.keyframes;
  if (keys.empty()) return l;
  if (auto v =
          keyed_value<double>(keys, time_s, [](const LightKeyframe& k) { return k.intensity; })) {
    l.intensity = *v;
  }
  if (auto v = keyed_value<Eigen::Vector3d>(keys, time_s,
                                            [](const LightKeyframe& k) { return k.position; })) {
    l.position = *v;
  }
  // Directions are kept as written (normalising is not idempotent in floating point and the
  // resolved scene must read back exactly); their unit vectors are interpolated.
  if (auto v = keyed_value<Eigen::Vector3d>(keys, time_s, [](const LightKeyframe& k) {
        return k.direction ? std::optional<Eigen::Vector3d>(k.direction->normalized())
                           : std::nullopt;
      })) {
    l.direction = v->normalized();
  }
  return l;
}

}  // namespace simcap
