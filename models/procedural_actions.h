// The action kinds of generate_procedural (jumps, a walking turn-around, squats, arms crossing,
// grapevine side steps, bending to the floor, front kicks, fast arm swings): names, checks, poses.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "models/motion_source.h"
#include "models/pose.h"
#include "models/skeleton.h"

namespace simcap::procedural {

// The kinds action_poses makes, in the order of ProceduralSpec's comment (turnaround, a walk, is
// made by the walking generator of procedural_motion.cpp).
const std::vector<std::string>& action_kinds();
bool is_action(const std::string& kind);

// What is wrong with the parameters of an action or of turnaround: the scene key at fault
// ("count", "duration", ...) and why, with the valid range; nothing when they are fine or the
// kind has none of its own.
struct ParameterProblem {
  std::string key, message;
};
std::optional<ParameterProblem> parameter_problem(const ProceduralSpec& spec);

// The action's pose at time t (seconds) for `skeleton` (from build_humanoid). Throws Error for
// the problems of parameter_problem and for a skeleton without the H-Anim joints.
std::function<Pose(double)> action_poses(const ProceduralSpec& spec, const Skeleton& skeleton);

// The turnaround's ground path at time t (any t): straight ahead along +Z at spec.speed_m_s for
// turnaround.distance_m, a 180 degree turn on a tight curve while slowing down, then straight
// back.
void turnaround_path(const ProceduralSpec& spec, double t, Eigen::Vector3d* ground,
                     double* heading);

}  // namespace simcap::procedural
