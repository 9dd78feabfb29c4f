// Where tracking starts: body dimensions and a first pose, either from ground-truth joints
// (--init gt, Moschini §7.1) or from the hull of a person standing upright (--init auto).
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "core/joint_track.h"
#include "tracker/moschini/icp_targets.h"
#include "tracker/moschini/stick_model.h"
#include "tracker/moschini/visual_hull.h"

namespace simcap::tracker {

using NamedJoints = std::map<std::string, Eigen::Vector3d>;

// The joints of `track` at `frame`; throws Error naming `source` when the frame is absent.
NamedJoints joints_at(const JointTrack& track, int frame, const std::string& source);

// Stick lengths and torso shape measured on one frame of H-Anim joints (at least the HE15 set;
// skull_tip and l/r_hand_tip are used when present, else the neutral humanoid's proportions
// extend the head and forearm sticks to the head top and finger tips). The torso axis runs
// from the hip midpoint to vc7; d_s and d_h are measured, as the thesis did on HumanEva.
BodyDimensions dimensions_from_joints(const NamedJoints& joints, const std::string& source);

// The stick pose closest to the joints: torso frame from hips, vc7 and shoulders; limbs pointed
// at the measured joints; the shoulder twist from the elbow's bending plane.
StickPose pose_from_joints(const StickModel& model, const NamedJoints& joints,
                           const std::string& source);

// How far the hull's centerline runs from the pelvis, chest and head joint lines on a frame
// whose pose is known: per stick, the median offset across its axis of the points nearest its
// middle (zero for the limbs, whose centroids follow the bones, and where too few points fall).
std::array<Eigen::Vector3d, kSegmentCount> measure_centerline_offsets(
    const StickModel& model, const StickPose& pose, const std::vector<Eigen::Vector3d>& points);

// Dimensions for a person of `height_m`: simcap's humanoid (Drillis-Contini proportions)
// scaled to that height, shoulders and hips included. (Table 5.3's d_s = 0.8
// and d_H = 0.7 describe HumanEva's joint centres: on H-Anim's they put the shoulders 8 cm low
// and the hips 4 cm wide.)
BodyDimensions dimensions_from_height(double height_m);
// How high that humanoid's ankles stand above the floor.
double ankle_height_from_height(double height_m);

// What the hull says about a person standing upright on the floor y = 0.
struct UprightCue {
  double top_y = 0;                                    // highest occupied voxel centre (head top)
  Eigen::Vector2d torso_xz = Eigen::Vector2d::Zero();  // hull centroid in the torso's height band
};
UprightCue upright_cue(const Occupancy& hull, const BodyDimensions& dims);

// Upright poses at `headings` headings around the circle, arms hanging slightly apart: starting
// points for ICP. (The feet do not tell the heading: mid-stride, the line from the shins' centroid
// to the feet's may point 90 degrees off it.)
std::vector<StickPose> upright_hypotheses(const StickModel& model, const UprightCue& cue,
                                          int headings);

}  // namespace simcap::tracker
