#include "sim/embree_scene.h"

#include <oneapi/tbb/parallel_for.h>

#include <string>

#include "core/error.h"
#include "sim/srgb.h"

namespace simcap {
namespace {

RTCGeometry new_triangle_geometry(RTCDevice device, const std::vector<Eigen::Vector3f>& vertices,
                                  const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertices.size()));
  auto* t = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), triangles.size()));
  if (!v || !t) {
    rtcReleaseGeometry(g);
    throw Error("Embree: cannot allocate geometry buffers");
  }
  for (size_t i = 0; i < vertices.size(); ++i) {
    for (int k = 0; k < 3; ++k) v[3 * i + k] = vertices[i][k];
  }
  for (size_t i = 0; i < triangles.size(); ++i) {
    for (int k = 0; k < 3; ++k) t[3 * i + k] = triangles[i][k];
  }
  return g;
}

}  // namespace

EmbreeScene::Entry EmbreeScene::actor_entry(int actor) {
  Entry e;
  e.actor = actor;
  return e;
}

namespace {

// A low-quality scene build makes Embree keep one BVH per geometry under a small top-level
// BVH, so a frame only updates the bodies' BVHs; the static geometry's stays as built.
RTCScene new_dynamic_scene(RTCDevice device) {
  RTCScene scene = rtcNewScene(device);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_LOW);
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_DYNAMIC);
  return scene;
}

}  // namespace

EmbreeScene::EmbreeScene(BodyBvhUpdate body_update, int time_steps, int still_step)
    : body_update_(body_update), time_steps_(time_steps), still_step_(still_step) {
  if (time_steps < 1 || time_steps > RTC_MAX_TIME_STEP_COUNT) {
    throw Error("Embree: time steps must be in [1, " + std::to_string(RTC_MAX_TIME_STEP_COUNT) +
                "], got " + std::to_string(time_steps));
  }
  if (still_step >= time_steps || (still_step >= 0 && time_steps == 1)) {
    throw Error("Embree: no still copy of time step " + std::to_string(still_step) + " of " +
                std::to_string(time_steps));
  }
  device_ = rtcNewDevice(nullptr);
  if (!device_) throw Error("Embree: cannot create a device");
  scene_ = new_dynamic_scene(device_);
  // Embree builds a geometry's BVH once per scene it is attached to: a casters' copy of a
  // motion-blur scene would build the bodies' motion-blur BVHs, the costliest part of a blurred
  // frame, twice; its shadow rays trace the whole scene instead (casters_of()).
  if (time_steps == 1) casters_ = new_dynamic_scene(device_);
  if (still_step >= 0) {
    still_scene_ = new_dynamic_scene(device_);
    still_casters_ = new_dynamic_scene(device_);
    // The time Embree gives step s of n: s / (n - 1), in float as the rays carry it.
    still_time_ = static_cast<float>(still_step) / static_cast<float>(time_steps - 1);
  }
}

EmbreeScene::~EmbreeScene() {
  for (auto& a : actors_) {
    if (!bodies_[a.body]->instanced_scene) continue;
    if (a.geometry) rtcReleaseGeometry(a.geometry);
    if (a.still_geometry) rtcReleaseGeometry(a.still_geometry);
  }
  for (auto& b : bodies_) {
    rtcReleaseGeometry(b->geometry);
    if (b->instanced_scene) rtcReleaseScene(b->instanced_scene);
    if (b->still_geometry) rtcReleaseGeometry(b->still_geometry);
    if (b->still_instanced_scene) rtcReleaseScene(b->still_instanced_scene);
  }
  if (still_scene_) rtcReleaseScene(still_scene_);
  if (still_casters_) rtcReleaseScene(still_casters_);
  if (casters_) rtcReleaseScene(casters_);
  rtcReleaseScene(scene_);
  rtcReleaseDevice(device_);
}

void EmbreeScene::check_device(const char* what) const {
  const RTCError e = rtcGetDeviceError(device_);
  if (e != RTC_ERROR_NONE) {
    throw Error(std::string("Embree: ") + what + " failed (error " + std::to_string(e) + ")");
  }
}

unsigned EmbreeScene::attach(RTCGeometry geometry, RTCGeometry still, Entry entry,
                             bool casts_shadows) {
  const unsigned id = rtcAttachGeometry(scene_, geometry);
  if (still_scene_ && still) rtcAttachGeometryByID(still_scene_, still, id);
  if (casts_shadows) {
    if (casters_) rtcAttachGeometryByID(casters_, geometry, id);
    if (still_casters_ && still) rtcAttachGeometryByID(still_casters_, still, id);
  }
  if (entries_.size() <= id) entries_.resize(id + 1);
  entries_[id] = entry;
  return id;
}

void EmbreeScene::add_static(const TriangleMesh& mesh, const StaticLook& look, bool casts_shadows) {
  if (mesh.triangles.empty()) return;
  RTCGeometry g = new_triangle_geometry(device_, mesh.vertices, mesh.triangles);
  rtcSetGeometryMask(g, casts_shadows ? kShadowCasterMask : kRoomMask);
  rtcSetGeometryBuildQuality(g, RTC_BUILD_QUALITY_HIGH);
  rtcCommitGeometry(g);
  auto s = std::make_unique<StaticGeometry>();
  s->look = look;
  s->triangles = mesh.triangles;
  s->normals = mesh.normals;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3f a = mesh.vertices[t[0]];
    s->face_normals.push_back(
        (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).normalized());
  }
  Entry e;
  e.face_normals = s->face_normals.data();
  e.vertex_normals = s->normals.empty() ? nullptr : s->normals.data();
  e.triangles = s->triangles.data();
  e.albedo = srgb_to_linear(look.color);
  e.texture = look.texture.get();
  e.tex_u = look.tex_u;
  e.tex_v = look.tex_v;
  statics_.push_back(std::move(s));
  attach(g, g, e, casts_shadows);
  rtcReleaseGeometry(g);
  check_device("adding static geometry");
}

int EmbreeScene::add_body(const BodyMesh& mesh, bool instanced) {
  auto body = std::make_unique<Body>();
  body->mesh = &mesh;
  const size_t nv = mesh.vertices.size(), nt = mesh.triangles.size();
  const size_t steps = static_cast<size_t>(time_steps_);
  body->vertices.assign(steps * 3 * nv + 1, 0.f);
  for (size_t s = 0; s < steps; ++s) {
    for (size_t i = 0; i < nv; ++i) {
      for (int k = 0; k < 3; ++k) body->vertices[(s * nv + i) * 3 + k] = mesh.vertices[i][k];
    }
  }
  body->face_normals.resize(steps * nt);
  body->vertex_normals.resize(steps * nv);
  body->vertex_face_start.assign(nv + 1, 0);
  for (const auto& t : mesh.triangles) {
    for (const auto v : t) ++body->vertex_face_start[v + 1];
  }
  for (size_t i = 0; i < nv; ++i) body->vertex_face_start[i + 1] += body->vertex_face_start[i];
  body->vertex_faces.resize(3 * nt);
  std::vector<std::uint32_t> fill(body->vertex_face_start.begin(),
                                  body->vertex_face_start.end() - 1);
  for (size_t f = 0; f < nt; ++f) {
    for (const auto v : mesh.triangles[f])
      body->vertex_faces[fill[v]++] = static_cast<std::uint32_t>(f);
  }

  body->geometry = new_body_geometry(*body, 0, time_steps_);
  if (instanced) body->instanced_scene = new_body_scene(body->geometry);
  if (still_scene_) {
    body->still_geometry = new_body_geometry(*body, still_step_, 1);
    if (instanced) body->still_instanced_scene = new_body_scene(body->still_geometry);
  }
  bodies_.push_back(std::move(body));
  body_updated(static_cast<int>(bodies_.size()) - 1);
  check_device("adding a body");
  return static_cast<int>(bodies_.size()) - 1;
}

RTCGeometry EmbreeScene::new_body_geometry(Body& body, int first_step, int steps) {
  const auto& mesh = *body.mesh;
  const size_t nv = mesh.vertices.size(), nt = mesh.triangles.size();
  RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  if (steps > 1) rtcSetGeometryTimeStepCount(g, static_cast<unsigned>(steps));
  for (int s = 0; s < steps; ++s) {
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, static_cast<unsigned>(s),
                               RTC_FORMAT_FLOAT3, body.vertices.data(),
                               static_cast<size_t>(first_step + s) * 3 * nv * sizeof(float),
                               3 * sizeof(float), nv);
  }
  auto* t = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), nt));
  if (!t) {
    rtcReleaseGeometry(g);
    throw Error("Embree: cannot allocate the body's index buffer");
  }
  for (size_t i = 0; i < nt; ++i) {
    for (int k = 0; k < 3; ++k) t[3 * i + k] = mesh.triangles[i][k];
  }
  rtcSetGeometryBuildQuality(
      g, body_update_ == BodyBvhUpdate::refit ? RTC_BUILD_QUALITY_REFIT : RTC_BUILD_QUALITY_LOW);
  rtcSetGeometryMask(g, kShadowCasterMask);
  return g;
}

RTCScene EmbreeScene::new_body_scene(RTCGeometry body_geometry) {
  RTCScene scene = new_dynamic_scene(device_);
  rtcAttachGeometry(scene, body_geometry);
  return scene;
}

int EmbreeScene::add_actor(int body_index, const std::array<Rgb, kMaterialRegionCount>& colors) {
  Body& body = *bodies_.at(body_index);
  Actor a;
  a.body = body_index;
  for (int i = 0; i < kMaterialRegionCount; ++i) a.albedo[i] = srgb_to_linear(colors[i]);
  const int index = static_cast<int>(actors_.size());
  if (body.instanced_scene) {
    auto instance = [this](RTCScene of) {
      RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
      rtcSetGeometryMask(g, kShadowCasterMask);
      rtcSetGeometryInstancedScene(g, of);
      return g;
    };
    a.geometry = instance(body.instanced_scene);
    if (body.still_instanced_scene) a.still_geometry = instance(body.still_instanced_scene);
  } else {
    if (body.attached) throw Error("a body that is not instanced can be worn by one actor only");
    a.geometry = body.geometry;
    a.still_geometry = body.still_geometry;
    body.attached = true;
  }
  attach(a.geometry, a.still_geometry, actor_entry(index), true);
  update_bounds(a);
  actors_.push_back(a);
  set_actor_transform(index, Eigen::Isometry3d::Identity());
  check_device("adding an actor");
  return index;
}

float* EmbreeScene::body_vertices(int body, int step) {
  if (step < 0 || step >= time_steps_) throw Error("Embree: no time step " + std::to_string(step));
  Body& b = *bodies_.at(body);
  return b.vertices.data() + static_cast<size_t>(step) * 3 * b.mesh->vertices.size();
}

void EmbreeScene::body_updated(int body_index) {
  Body& b = *bodies_.at(body_index);
  const auto& tris = b.mesh->triangles;
  const size_t nv = b.mesh->vertices.size(), nt = tris.size();
  for (size_t step = 0; step < static_cast<size_t>(time_steps_); ++step) {
    const float* v = b.vertices.data() + step * 3 * nv;
    Eigen::Vector3f* face_normals = b.face_normals.data() + step * nt;
    Eigen::Vector3f* vertex_normals = b.vertex_normals.data() + step * nv;
    auto vertex = [v](std::uint32_t i) {
      return Eigen::Vector3f(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
    };
    tbb::parallel_for(tbb::blocked_range<size_t>(0, nt, 4096), [&](const auto& r) {
      for (size_t f = r.begin(); f != r.end(); ++f) {
        const Eigen::Vector3f a = vertex(tris[f][0]);
        face_normals[f] = (vertex(tris[f][1]) - a).cross(vertex(tris[f][2]) - a);
      }
    });
    // Area-weighted vertex normals: summing unnormalised face normals weights each by its area.
    tbb::parallel_for(tbb::blocked_range<size_t>(0, nv, 4096), [&](const auto& r) {
      for (size_t i = r.begin(); i != r.end(); ++i) {
        Eigen::Vector3f n = Eigen::Vector3f::Zero();
        for (auto k = b.vertex_face_start[i]; k < b.vertex_face_start[i + 1]; ++k) {
          n += face_normals[b.vertex_faces[k]];
        }
        const float len = n.norm();
        vertex_normals[i] = len > 0 ? Eigen::Vector3f(n / len) : Eigen::Vector3f::UnitY();
      }
    });
    rtcUpdateGeometryBuffer(b.geometry, RTC_BUFFER_TYPE_VERTEX, static_cast<unsigned>(step));
  }
  rtcCommitGeometry(b.geometry);
  if (b.instanced_scene) rtcCommitScene(b.instanced_scene);
  b.bounds.setEmpty();
  for (size_t i = 0; i < nv * static_cast<size_t>(time_steps_); ++i) {
    b.bounds.extend(
        Eigen::Vector3f(b.vertices[3 * i], b.vertices[3 * i + 1], b.vertices[3 * i + 2]));
  }
  for (Actor& a : actors_) {
    if (a.body == body_index) update_bounds(a);
  }
  if (b.still_geometry) {
    rtcUpdateGeometryBuffer(b.still_geometry, RTC_BUFFER_TYPE_VERTEX, 0);
    rtcCommitGeometry(b.still_geometry);
    if (b.still_instanced_scene) rtcCommitScene(b.still_instanced_scene);
  }
}

void EmbreeScene::set_actor_transform(int actor, const Eigen::Isometry3d& object_to_world) {
  Actor& a = actors_.at(actor);
  if (!bodies_[a.body]->instanced_scene) return;
  const Eigen::Matrix<float, 3, 4> m = object_to_world.matrix().topRows<3>().cast<float>();
  for (RTCGeometry g : {a.geometry, a.still_geometry}) {
    if (!g) continue;
    rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, m.data());
    rtcCommitGeometry(g);
  }
  a.rotation = m.leftCols<3>();
  a.object_to_world.matrix().topRows<3>() = m;
  update_bounds(a);
}

void EmbreeScene::update_bounds(Actor& a) {
  const Eigen::AlignedBox3f& object = bodies_[a.body]->bounds;
  a.bounds.setEmpty();
  if (object.isEmpty()) return;
  for (int corner = 0; corner < 8; ++corner) {
    a.bounds.extend(a.object_to_world *
                    object.corner(static_cast<Eigen::AlignedBox3f::CornerType>(corner)));
  }
  // Rounding in the slab test and in Embree's own is far below a millimetre.
  a.bounds.min().array() -= 1e-3f;
  a.bounds.max().array() += 1e-3f;
}

void EmbreeScene::set_actors_visible(bool visible) {
  for (auto& a : actors_) {
    for (RTCGeometry g : {a.geometry, a.still_geometry}) {
      if (!g) continue;
      if (visible) {
        rtcEnableGeometry(g);
      } else {
        rtcDisableGeometry(g);
      }
      rtcCommitGeometry(g);
    }
  }
}

void EmbreeScene::commit() {
  for (RTCScene s : {scene_, still_scene_, casters_, still_casters_}) {
    if (s) rtcCommitScene(s);
  }
  check_device("building the scene");
}

int EmbreeScene::actor_of(const HitRecord& hit) const {
  return entries_[hit.inst_id != RTC_INVALID_GEOMETRY_ID ? hit.inst_id : hit.geom_id].actor;
}

}  // namespace simcap
