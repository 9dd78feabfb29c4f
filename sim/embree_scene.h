// The ray-tracing scene: one Embree device and scene holding the static room and occluders
// (built once) and the actors' skinned bodies (vertex buffers rewritten and the BVH updated every
// frame), and the lookup from an Embree hit to what was hit: actor, body part, colour, normal.
#pragma once

#include <embree3/rtcore.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <memory>
#include <vector>

#include "models/body_mesh.h"
#include "scenes/scene.h"
#include "sim/scene_meshes.h"
#include "sim/texture.h"

namespace simcap {

// How a body's BVH follows its vertices from frame to frame. `simcap bench render` measures
// both on studio4: refitting the BVH built on the first pose takes 0.85 ms a frame, rebuilding
// it 1.7 ms (2 idle cores), and tracing costs the same within noise, so refit is the default.
enum class BodyBvhUpdate { refit, rebuild };

// What a ray hit, in Embree's terms (instance, geometry and triangle ids, barycentrics).
struct HitRecord {
  unsigned geom_id = RTC_INVALID_GEOMETRY_ID;
  unsigned inst_id = RTC_INVALID_GEOMETRY_ID;
  unsigned prim_id = 0;
  float u = 0, v = 0;
  Eigen::Vector3f ng = Eigen::Vector3f::Zero();  // unnormalised, in the hit object's frame
  float time = 0;                                // the ray's time (moving bodies)
};

// The surface at a hit, ready for shading and labelling.
struct SurfacePoint {
  int actor = -1;  // index of the actor hit, -1 for the room and occluders
  int part = 0;    // part label (1 + skeleton joint index of the segment), 0 off the bodies
  Eigen::Vector3f albedo = Eigen::Vector3f::Zero();   // linear RGB
  Eigen::Vector3f normal = Eigen::Vector3f::UnitY();  // unit shading normal, facing the ray
  Eigen::Vector3f geometric_normal = Eigen::Vector3f::UnitY();  // unit, facing the ray
};

// Appearance of a static surface: a uniform sRGB colour, or a texture tiled in metres along
// the world directions tex_u and tex_v.
struct StaticLook {
  Rgb color{0.5f, 0.5f, 0.5f};
  std::shared_ptr<const Texture> texture;
  Eigen::Vector3f tex_u = Eigen::Vector3f::UnitX();
  Eigen::Vector3f tex_v = Eigen::Vector3f::UnitZ();
};

// Embree ray masks. Shadow rays only test kShadowCasterMask: the room's own surfaces never cast
// shadows, because lights stand for studio lights inside the room (a directional light would
// otherwise be blocked by the ceiling). Camera rays test everything.
inline constexpr unsigned kRoomMask = 1u;
inline constexpr unsigned kShadowCasterMask = 2u;

class EmbreeScene {
 public:
  // Bodies get `time_steps` vertex buffers (Embree motion blur: a ray at time t in [0, 1] sees
  // the body interpolated linearly between the steps around t); 1 keeps them still.
  // `still_step` >= 0 adds a still scene: the room, the occluders and every body frozen at that
  // time step (sharing its vertices), for the rays at exactly that step's time (scene_at):
  // Embree traverses motion-blur geometry 1.7x slower than still geometry, even between steps
  // that are equal.
  explicit EmbreeScene(BodyBvhUpdate body_update = BodyBvhUpdate::refit, int time_steps = 1,
                       int still_step = -1);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Static geometry; `casts_shadows` = false for the room's floor, walls and ceiling.
  void add_static(const TriangleMesh& mesh, const StaticLook& look, bool casts_shadows);

  // A body mesh (kept by reference: it must outlive the scene). A body worn by one actor is
  // posed directly in world coordinates; an `instanced` body is posed once in its motion's own
  // frame and every actor wearing it sees it through its own transform (set_actor_transform).
  int add_body(const BodyMesh& mesh, bool instanced);
  // An actor wearing `body` in the given sRGB colours (skin, shirt, trousers, shoes, hair).
  // Actors are numbered in the order they are added.
  int add_actor(int body, const std::array<Rgb, kMaterialRegionCount>& colors);

  // The body's vertex buffer of time step `step` (3 * vertex count + 1 floats) for
  // Skinner::skin to write into; call body_updated() after writing every step.
  float* body_vertices(int body, int step = 0);
  int time_steps() const { return time_steps_; }
  void body_updated(int body);
  void set_actor_transform(int actor, const Eigen::Isometry3d& object_to_world);
  // Hides or shows every actor (the empty-room background plates hide them).
  void set_actors_visible(bool visible);
  // Applies all changes; throws Error when Embree reports one.
  void commit();

  RTCScene handle() const { return scene_; }
  // The scene for rays at `time`: the still scene at its step's time, otherwise handle(). Both
  // give the same geometry ids, and the same hits at that time.
  RTCScene scene_at(float time) const {
    return still_scene_ && time == still_time_ ? still_scene_ : scene_;
  }
  // The scene for rays at any times of the steps: the still scene when none of them passes
  // through a box that holds an actor's body at every time (1 mm wider), otherwise handle().
  // Rays (lanes where `valid`) start at org, go along dir and end at far (may be infinite).
  template <int N>
  RTCScene scene_for(const int* valid, const float* const org[3], const float* const dir[3],
                     const float* far) const;
  // What shadow rays trace where camera rays trace `scene` (scene_at's or scene_for's answer):
  // the same geometry ids but only the shadow casters (actors and occluders), so that shadow rays
  // never traverse the room's surfaces, which their mask would reject at every triangle anyway.
  // A motion-blur scene has no casters' copy: its shadow rays trace the scene itself.
  RTCScene casters_of(RTCScene scene) const {
    if (scene == still_scene_) return still_casters_;
    return casters_ ? casters_ : scene_;
  }
  int actor_count() const { return static_cast<int>(actors_.size()); }

  // The actor a hit belongs to (-1: room or occluder); cheaper than surface().
  int actor_of(const HitRecord& hit) const;
  // True when every point of the hit triangle looks the same from a camera (static, flat
  // shaded, untextured): rays from one origin also see the same side of a flat triangle.
  bool uniform_surface(const HitRecord& hit) const {
    const Entry& e = entries_[hit.inst_id != RTC_INVALID_GEOMETRY_ID ? hit.inst_id : hit.geom_id];
    return e.actor < 0 && !e.vertex_normals && !e.texture;
  }
  // Inline: the renderer calls it for every hit.
  SurfacePoint surface(const HitRecord& hit, const Eigen::Vector3f& position,
                       const Eigen::Vector3f& ray_direction) const;

 private:
  struct StaticGeometry {
    StaticLook look;  // keeps the texture alive
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<Eigen::Vector3f> face_normals;  // unit, per triangle
    std::vector<Eigen::Vector3f> normals;       // per vertex, or empty for flat shading
  };
  struct Body {
    const BodyMesh* mesh = nullptr;
    RTCGeometry geometry = nullptr;
    RTCScene instanced_scene = nullptr;  // only for instanced bodies
    // The body at the still step, and its instanced scene, when there is a still scene.
    RTCGeometry still_geometry = nullptr;
    RTCScene still_instanced_scene = nullptr;
    std::vector<float> vertices;  // shared with Embree: the time steps one after another
    std::vector<Eigen::Vector3f> face_normals, vertex_normals;   // per step, one after another
    std::vector<std::uint32_t> vertex_face_start, vertex_faces;  // vertex -> triangles (CSR)
    bool attached = false;
    Eigen::AlignedBox3f bounds;  // object frame: every time step's vertices
  };
  struct Actor {
    int body = -1;
    RTCGeometry geometry = nullptr;        // the body itself, or the actor's instance of it
    RTCGeometry still_geometry = nullptr;  // the same in the still scene
    std::array<Eigen::Vector3f, kMaterialRegionCount> albedo;  // linear
    Eigen::Matrix3f rotation = Eigen::Matrix3f::Identity();    // object -> world
    Eigen::Isometry3f object_to_world = Eigen::Isometry3f::Identity();
    Eigen::AlignedBox3f bounds;  // world: the body at every time step, 1 mm wider
  };
  // What a top-level geometry id stands for, flattened so that a hit on the room, the commonest
  // case, costs two dependent loads.
  struct Entry {
    int actor = -1;  // >= 0: that actor's body (or its instance); otherwise static geometry
    const Eigen::Vector3f* face_normals = nullptr;    // static: unit, per triangle
    const Eigen::Vector3f* vertex_normals = nullptr;  // static, smooth shading only
    const std::array<std::uint32_t, 3>* triangles = nullptr;
    Eigen::Vector3f albedo = Eigen::Vector3f::Zero();  // static, linear
    const Texture* texture = nullptr;
    Eigen::Vector3f tex_u = Eigen::Vector3f::Zero(), tex_v = Eigen::Vector3f::Zero();
  };
  static Entry actor_entry(int actor);
  void update_bounds(Actor& actor);
  // Attaches `geometry` to the scene and `still` (if any) to the still scene, under one id, and
  // each to its casters' scene when it casts shadows.
  unsigned attach(RTCGeometry geometry, RTCGeometry still, Entry entry, bool casts_shadows);
  // A body's triangle geometry reading `steps` time steps from `first_step` of its vertices.
  RTCGeometry new_body_geometry(Body& body, int first_step, int steps);
  RTCScene new_body_scene(RTCGeometry body_geometry);
  void check_device(const char* what) const;

  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  RTCScene still_scene_ = nullptr;
  RTCScene casters_ = nullptr, still_casters_ = nullptr;  // see casters_of(); may be null
  BodyBvhUpdate body_update_;
  int time_steps_ = 1;
  int still_step_ = -1;
  float still_time_ = 0;
  std::vector<std::unique_ptr<StaticGeometry>> statics_;  // stable addresses for entries_
  std::vector<std::unique_ptr<Body>> bodies_;
  std::vector<Actor> actors_;
  std::vector<Entry> entries_;
};

template <int N>
RTCScene EmbreeScene::scene_for(const int* valid, const float* const org[3],
                                const float* const dir[3], const float* far) const {
  if (!still_scene_) return scene_;
  alignas(64) float inverse[3][N];
  for (int c = 0; c < 3; ++c) {
    for (int k = 0; k < N; ++k) inverse[c][k] = 1.f / dir[c][k];
  }
  for (const Actor& a : actors_) {
    const Eigen::Vector3f lo = a.bounds.min(), hi = a.bounds.max();
    // Slab test, branch-free so that it vectorises. A direction parallel to a slab gives
    // infinite distances (the ray is in the slab throughout or never), or NaN for an origin on
    // its plane, where the margin keeps the body off the ray whatever the test answers.
    int near = 0;
    for (int k = 0; k < N; ++k) {
      float t0 = 0.f, t1 = far[k];
      for (int c = 0; c < 3; ++c) {
        const float ta = (lo[c] - org[c][k]) * inverse[c][k];
        const float tb = (hi[c] - org[c][k]) * inverse[c][k];
        t0 = std::max(t0, std::min(ta, tb));
        t1 = std::min(t1, std::max(ta, tb));
      }
      near |= valid[k] & -static_cast<int>(t0 <= t1);
    }
    if (near) return scene_;
  }
  return still_scene_;
}

inline SurfacePoint EmbreeScene::surface(const HitRecord& hit, const Eigen::Vector3f& position,
                                         const Eigen::Vector3f& ray_direction) const {
  SurfacePoint s;
  const Entry& e = entries_[hit.inst_id != RTC_INVALID_GEOMETRY_ID ? hit.inst_id : hit.geom_id];
  const float w0 = 1.f - hit.u - hit.v;
  if (e.actor >= 0) {
    const Actor& a = actors_[e.actor];
    const Body& b = *bodies_[a.body];
    const auto& tri = b.mesh->triangles[hit.prim_id];
    s.actor = e.actor;
    s.albedo = a.albedo[static_cast<int>(b.mesh->triangle_material[hit.prim_id])];
    const Eigen::Vector3f* vn = b.vertex_normals.data();
    Eigen::Vector3f n = w0 * vn[tri[0]] + hit.u * vn[tri[1]] + hit.v * vn[tri[2]];
    if (time_steps_ > 1) {
      // Normals are kept per time step: blend the two steps around the ray's time.
      const float step = hit.time * static_cast<float>(time_steps_ - 1);
      const int i = std::clamp(static_cast<int>(step), 0, time_steps_ - 2);
      const float a = step - static_cast<float>(i);
      const size_t nv = b.mesh->vertices.size();
      const Eigen::Vector3f* v0 = vn + i * nv;
      const Eigen::Vector3f* v1 = v0 + nv;
      n = (1 - a) * (w0 * v0[tri[0]] + hit.u * v0[tri[1]] + hit.v * v0[tri[2]]) +
          a * (w0 * v1[tri[0]] + hit.u * v1[tri[1]] + hit.v * v1[tri[2]]);
    }
    s.normal = (a.rotation * n).normalized();
    s.geometric_normal = (a.rotation * hit.ng).normalized();
    // The part is the segment of the triangle's vertex nearest to the hit.
    const std::uint32_t nearest =
        w0 >= hit.u ? (w0 >= hit.v ? tri[0] : tri[2]) : (hit.u >= hit.v ? tri[1] : tri[2]);
    s.part = 1 + b.mesh->vertex_segment[nearest];
  } else {
    s.actor = -1;
    s.part = 0;
    s.geometric_normal = e.face_normals[hit.prim_id];
    if (e.vertex_normals) {
      const auto& tri = e.triangles[hit.prim_id];
      s.normal = (w0 * e.vertex_normals[tri[0]] + hit.u * e.vertex_normals[tri[1]] +
                  hit.v * e.vertex_normals[tri[2]])
                     .normalized();
    } else {
      s.normal = s.geometric_normal;
    }
    s.albedo =
        e.texture ? e.texture->sample(position.dot(e.tex_u), position.dot(e.tex_v)) : e.albedo;
  }
  if (s.geometric_normal.dot(ray_direction) > 0) {
    s.geometric_normal = -s.geometric_normal;
    s.normal = -s.normal;
  }
  return s;
}

}  // namespace simcap
