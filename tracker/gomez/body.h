// The monocular tracker's articulated body in one place: its sized skeleton, the DOF state on
// it, the capsules it is rendered with and the arms' (and the full body's legs') analytic
// kinematics.
#pragma once

#include <optional>

#include "models/pose.h"
#include "models/skeleton.h"
#include "tracker/gomez/arm_kinematics.h"
#include "tracker/gomez/body_dofs.h"
#include "tracker/gomez/body_shape.h"

namespace simcap::tracker::gomez {

struct Body {
  // The members refer to each other: a Body is neither copied nor moved.
  // `on_floor`: the full body's feet stay on the floor (BodyDofs' floor contacts).
  Body(Skeleton skeleton_in, BodyKind kind, const Pose& first, bool on_floor = true,
       const ShapeScales& scales = {})
      : skeleton(std::move(skeleton_in)),
        shape(make_body_shape(skeleton, kind, scales)),
        dofs(skeleton, kind, first,
             on_floor ? sole_points(shape, skeleton) : std::vector<FloorContact>{}),
        arms(dofs),
        legs(kind == BodyKind::full ? std::optional<ArmKinematics>(std::in_place, dofs, Limbs::legs)
                                    : std::nullopt) {}
  Body(const Body&) = delete;
  Body& operator=(const Body&) = delete;

  Skeleton skeleton;
  BodyShape shape;
  BodyDofs dofs;
  ArmKinematics arms;
  std::optional<ArmKinematics> legs;  // the full body's
};

}  // namespace simcap::tracker::gomez
