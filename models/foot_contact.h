// How well feet meet the floor (y = 0) in a motion: the height of the lowest foot point per frame
// and foot sliding (horizontal speed of foot points while they touch the floor).
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "models/motion.h"
#include "models/skeleton.h"

namespace simcap {

// World points of the left and right foot, per frame.
struct FootTrack {
  double fps = 30.0;
  std::vector<std::array<std::vector<Eigen::Vector3d>, 2>> frames;
};

struct FootStats {
  int frames = 0;
  double floor = 0.0;        // metres: the floor height the figures are relative to
  double lowest_min = 0.0;   // metres: minimum over frames of the lowest foot point's height
  double lowest_mean = 0.0;  // metres: mean over frames of the lowest foot point's height
  // A contact is a run of at least min_contact_s during which a foot point stays within
  // contact_height of the floor (shorter runs are swing feet skimming the floor).
  int contacts = 0;
  double contact_s = 0.0;     // seconds of contact, summed over the points of both feet
  double slide_mean = 0.0;    // m/s: mean horizontal speed of foot points in contact
  double slide_median = 0.0;  // m/s: its median (robust to a few fast frames)
  double drift_mean = 0.0;    // metres: mean horizontal distance from a contact's start to its end
  double drift_max = 0.0;     // metres: the largest such distance
  double contact_height = 0.0, min_contact_s = 0.0;  // the thresholds used
  std::string summary() const;                       // one line for people
};

// Foot figures relative to the floor at height `floor`.
FootStats measure_feet(const FootTrack& track, double contact_height = 0.02,
                       double min_contact_s = 0.1, double floor = 0.0);

// The median over frames of the lowest foot point's height: where the floor is when some foot
// is down in most frames (walking, standing).
double median_lowest_point(const FootTrack& track);

// Sole points of a simcap humanoid (H-Anim names): heel, ball and toe tip of each foot, put on
// the floor plane under l/r_talocrural, l/r_metatarsophalangeal_2 and l/r_toe_tip in the neutral
// pose (the heel a third of the ankle-to-toe distance behind the ankle, as in the
// Drillis-Contini foot) and carried by the talocrural (heel, ball) and toe joints.
FootTrack humanoid_feet(const Skeleton& skeleton, const Motion& motion);

}  // namespace simcap
