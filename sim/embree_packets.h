// Ray packets of a compile-time width for Embree's packet API (rtcIntersect1/4/8/16 and
// rtcOccluded1/4/8/16), with the square-ish pixel block each width covers.
#pragma once

#include <embree3/rtcore.h>

#include <Eigen/Core>
#include <limits>

namespace simcap {

// Pixel block of a packet: 1x1, 2x2, 4x2 or 4x4.
template <int N>
struct PacketShape {
  static_assert(N == 1 || N == 4 || N == 8 || N == 16, "Embree packets hold 1, 4, 8 or 16 rays");
  static constexpr int width = N >= 8 ? 4 : (N == 4 ? 2 : 1);
  static constexpr int height = N / width;
};

template <int N>
struct alignas(64) RayHitPacket : RTCRayHitNt<N> {};
template <int N>
struct alignas(64) RayPacket : RTCRayNt<N> {};

// Lane k of a camera-ray packet starts at `origin` over [0, inf), sees every geometry and has
// no hit yet; the caller sets its direction.
template <int N>
void start_camera_ray(RayHitPacket<N>& packet, int k, const Eigen::Vector3f& origin, unsigned id) {
  packet.ray.org_x[k] = origin.x();
  packet.ray.org_y[k] = origin.y();
  packet.ray.org_z[k] = origin.z();
  packet.ray.tnear[k] = 0.f;
  packet.ray.tfar[k] = std::numeric_limits<float>::infinity();
  packet.ray.time[k] = 0.f;
  packet.ray.mask[k] = ~0u;
  packet.ray.id[k] = id;
  packet.ray.flags[k] = 0;
  packet.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
  packet.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
}

template <int N>
void intersect_packet(const int* valid, RTCScene scene, RTCIntersectContext* context,
                      RayHitPacket<N>& packet) {
  if constexpr (N == 1) {
    if (valid[0]) rtcIntersect1(scene, context, reinterpret_cast<RTCRayHit*>(&packet));
  } else if constexpr (N == 4) {
    rtcIntersect4(valid, scene, context, reinterpret_cast<RTCRayHit4*>(&packet));
  } else if constexpr (N == 8) {
    rtcIntersect8(valid, scene, context, reinterpret_cast<RTCRayHit8*>(&packet));
  } else {
    rtcIntersect16(valid, scene, context, reinterpret_cast<RTCRayHit16*>(&packet));
  }
}

// Occluded rays come back with tfar = -inf.
template <int N>
void occluded_packet(const int* valid, RTCScene scene, RTCIntersectContext* context,
                     RayPacket<N>& packet) {
  if constexpr (N == 1) {
    if (valid[0]) rtcOccluded1(scene, context, reinterpret_cast<RTCRay*>(&packet));
  } else if constexpr (N == 4) {
    rtcOccluded4(valid, scene, context, reinterpret_cast<RTCRay4*>(&packet));
  } else if constexpr (N == 8) {
    rtcOccluded8(valid, scene, context, reinterpret_cast<RTCRay8*>(&packet));
  } else {
    rtcOccluded16(valid, scene, context, reinterpret_cast<RTCRay16*>(&packet));
  }
}

}  // namespace simcap
