// Test support for the inverse-kinematics baselines (CCD, DLS): world joint positions of a pose,
// and the check that a solver never leaves the joint limits whatever it is asked to reach.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "models/pose.h"
#include "tracker/unzueta/sik_body.h"
#include "tracker/unzueta/sik_ik_solver.h"

namespace simcap::testing {

std::vector<Eigen::Vector3d> world_positions(const SikBody& body, const Pose& pose);

// Solves `trials` random target sets (wrists and ankles up to 0.8 m around the neutral pelvis,
// drawn from `seed`) and expects every joint of every result within SikLimits.
void expect_within_limits(IkSolver& solver, unsigned seed, int trials);

}  // namespace simcap::testing
