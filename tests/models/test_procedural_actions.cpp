// The action kinds of generate_procedural (and turnaround) against what a real body does: joints
// within the humanoid's limits, stance feet planted without sliding or sinking, no velocity
// jumps, balance over the feet when standing still, a ballistic flight when jumping, and each
// kind doing what its parameters say; for bodies from 1.5 to 2.0 m and the parameters' extremes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "core/error.h"
#include "models/body_mass.h"
#include "models/foot_contact.h"
#include "models/humanoid.h"
#include "models/joint_limits.h"
#include "models/motion_source.h"
#include "models/pose.h"
#include "models/procedural_actions.h"

namespace simcap {
namespace {

constexpr double kPi = std::numbers::pi;

const std::vector<std::string> kKinds = {"jumps",      "turnaround",   "squat", "arms_cross",
                                         "side_steps", "bend_forward", "kick",  "arm_swings"};

ProceduralSpec spec_of(const std::string& kind, double duration = 6.0) {
  ProceduralSpec spec;
  spec.kind = kind;
  spec.duration_s = duration;
  return spec;
}

// The parameters at the ends of their ranges, with the durations they need.
std::vector<ProceduralSpec> extremes(const std::string& kind) {
  std::vector<ProceduralSpec> out;
  const auto add = [&](double duration, const std::function<void(ProceduralSpec&)>& set) {
    ProceduralSpec s = spec_of(kind, duration);
    set(s);
    out.push_back(s);
  };
  if (kind == "jumps") {
    add(2.0, [](ProceduralSpec& s) { s.jumps = {1, 0.0, 0.05}; });
    add(5.0, [](ProceduralSpec& s) { s.jumps = {2, 1.0, 0.5}; });
  } else if (kind == "turnaround") {
    add(4.0, [](ProceduralSpec& s) { s.speed_m_s = 1.6, s.turnaround.distance_m = 1.0; });
    add(9.0, [](ProceduralSpec& s) { s.speed_m_s = 0.6, s.turnaround.distance_m = 2.0; });
  } else if (kind == "squat") {
    add(2.0, [](ProceduralSpec& s) { s.squat = {1, 0.05}; });
    add(4.0, [](ProceduralSpec& s) { s.squat = {2, 0.45}; });
  } else if (kind == "arms_cross") {
    add(1.5, [](ProceduralSpec& s) { s.arms_cross.count = 1; });
    add(5.5, [](ProceduralSpec& s) { s.arms_cross.count = 5; });
  } else if (kind == "side_steps") {
    add(2.5, [](ProceduralSpec& s) { s.side_steps = {1, 0.48}; });
    add(6.0, [](ProceduralSpec& s) { s.side_steps = {3, -2.64}; });
  } else if (kind == "bend_forward") {
    add(2.5, [](ProceduralSpec& s) { s.bend_forward.count = 1; });
    add(7.0, [](ProceduralSpec& s) { s.bend_forward.count = 3; });
  } else if (kind == "kick") {
    add(4.0, [](ProceduralSpec& s) { s.kick = {2, 0.2}; });
    add(4.0, [](ProceduralSpec& s) { s.kick = {2, 0.9}; });
  } else {
    add(3.0, [](ProceduralSpec& s) { s.arm_swings = {2.0, 120}; });
    add(6.0, [](ProceduralSpec& s) { s.arm_swings = {0.2, 5}; });
  }
  return out;
}

std::string describe(const ProceduralSpec& s, double height) {
  return s.kind + " for " + std::to_string(s.duration_s) + " s, body " + std::to_string(height) +
         " m";
}

// The largest amount (rad) by which a joint leaves its limits, and where.
double worst_limit_excess(const Skeleton& s, const Motion& m, std::string* where) {
  double worst = 0;
  for (size_t f = 0; f < m.frames.size(); ++f) {
    for (const JointLimits& l : humanoid_joint_limits()) {
      const double e = limit_excess(l, m.frames[f].rotations[s.require(l.joint)]);
      if (e > worst) {
        worst = e;
        *where = l.joint + " at frame " + std::to_string(f);
      }
    }
  }
  return worst;
}

// The largest acceleration (m/s^2) of any joint or site, from second differences.
double max_acceleration(const Skeleton& s, const Motion& m) {
  double worst = 0;
  std::vector<std::vector<Eigen::Vector3d>> p;
  for (const Pose& pose : m.frames) p.push_back(joint_positions(s, pose));
  for (size_t f = 1; f + 1 < p.size(); ++f) {
    for (int j = 0; j < s.size(); ++j) {
      worst = std::max(worst, (p[f + 1][j] - 2 * p[f][j] + p[f - 1][j]).norm() * m.fps * m.fps);
    }
  }
  return worst;
}

// Distance (x, z) from `p` to the convex hull of `points` (0 inside).
double distance_to_hull(const Eigen::Vector2d& p, std::vector<Eigen::Vector2d> points) {
  std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  const auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a,
                        const Eigen::Vector2d& b) {
    return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
  };
  std::vector<Eigen::Vector2d> hull;  // Andrew's monotone chain, counter-clockwise
  for (int pass = 0; pass < 2; ++pass) {
    const size_t start = hull.size();
    for (const auto& q : points) {
      while (hull.size() >= start + 2 && cross(hull[hull.size() - 2], hull.back(), q) <= 0) {
        hull.pop_back();
      }
      hull.push_back(q);
    }
    hull.pop_back();
    std::reverse(points.begin(), points.end());
  }
  bool inside = hull.size() >= 3;
  double best = INFINITY;
  for (size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d& a = hull[i];
    const Eigen::Vector2d& b = hull[(i + 1) % hull.size()];
    inside = inside && cross(a, b, p) >= 0;
    const double t = (b - a).squaredNorm() > 0
                         ? std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0)
                         : 0.0;
    best = std::min(best, (a + t * (b - a) - p).norm());
  }
  return inside ? 0.0 : best;
}

TEST(ProceduralActions, AreKindsOfTheGenerator) {
  for (const auto& kind : kKinds) {
    const auto& all = procedural_kinds();
    EXPECT_NE(std::find(all.begin(), all.end(), kind), all.end()) << kind;
    EXPECT_EQ(procedural::is_action(kind), kind != "turnaround") << kind;
  }
}

TEST(ProceduralActions, DefaultsAreValid) {
  for (const auto& kind : kKinds) {
    ProceduralSpec spec;
    spec.kind = kind;
    const auto problem = procedural::parameter_problem(spec);
    EXPECT_FALSE(problem) << kind << ": " << problem->key << " " << problem->message;
  }
}

TEST(ProceduralActions, StayWithinJointLimitsForEveryBodyAndTheParametersExtremes) {
  for (const double height : {1.5, 1.75, 2.0}) {
    const Skeleton s = build_humanoid({.height = height, .proportions = {}});
    for (const auto& kind : kKinds) {
      std::vector<ProceduralSpec> specs = extremes(kind);
      specs.push_back(spec_of(kind));
      for (const ProceduralSpec& spec : specs) {
        std::string where;
        const double excess = worst_limit_excess(s, generate_procedural(spec, s, 15), &where);
        // 1.5 degrees: the soft guards that keep ankles and hips inside their ranges.
        EXPECT_LT(excess, 1.5 * kPi / 180) << describe(spec, height) << ": " << where;
      }
    }
  }
}

TEST(ProceduralActions, StanceFeetNeitherSlideNorSink) {
  for (const double height : {1.5, 2.0}) {
    const Skeleton s = build_humanoid({.height = height, .proportions = {}});
    for (const auto& kind : kKinds) {
      std::vector<ProceduralSpec> specs = extremes(kind);
      specs.push_back(spec_of(kind));
      for (const ProceduralSpec& spec : specs) {
        const FootTrack track = humanoid_feet(s, generate_procedural(spec, s, 50));
        // Sole points within 5 mm of the floor for 0.1 s are in contact; they only roll about
        // the ball as a heel rises or comes down.
        const FootStats feet = measure_feet(track, 0.005, 0.1);
        EXPECT_GT(feet.lowest_min, -1e-6) << describe(spec, height);
        EXPECT_LT(feet.drift_max, 0.015) << describe(spec, height);
        EXPECT_LT(feet.slide_median, 1e-3) << describe(spec, height);
        EXPECT_GT(feet.contacts, 0) << describe(spec, height);
      }
    }
  }
}

TEST(ProceduralActions, VelocitiesNeverJump) {
  // A velocity jump dv shows as an acceleration dv * fps at one frame, growing with the frame
  // rate; a smooth motion's accelerations do not.
  const Skeleton s = build_humanoid();
  for (const auto& kind : kKinds) {
    std::vector<ProceduralSpec> specs = extremes(kind);
    specs.push_back(spec_of(kind));
    for (const ProceduralSpec& spec : specs) {
      const double coarse = max_acceleration(s, generate_procedural(spec, s, 100));
      const double fine = max_acceleration(s, generate_procedural(spec, s, 200));
      EXPECT_LT(fine, 1.5 * coarse) << describe(spec, 1.75);
      EXPECT_LT(fine, 600) << describe(spec, 1.75);  // m/s^2 anywhere on the body
    }
  }
}

TEST(ProceduralActions, StandingActionsKeepTheCentreOfMassOverTheFeet) {
  const Skeleton s = build_humanoid();
  const BodyMass mass(s);
  for (const char* kind : {"squat", "arms_cross", "bend_forward", "kick", "arm_swings"}) {
    const Motion m = generate_procedural(spec_of(kind), s, 30);
    const FootTrack track = humanoid_feet(s, m);
    double worst = 0;
    for (size_t f = 0; f < m.frames.size(); ++f) {
      std::vector<Eigen::Vector2d> support;
      for (const auto& foot : track.frames[f]) {
        for (const auto& p : foot) {
          if (p.y() < 0.005) support.emplace_back(p.x(), p.z());
        }
      }
      const Eigen::Vector3d com = mass.center(joint_positions(s, m.frames[f]));
      worst = std::max(worst, distance_to_hull({com.x(), com.z()}, support));
    }
    // The sole points lie on each foot's mid-line, so one foot's support is a segment; the
    // real sole is 4 cm either side of it.
    EXPECT_LT(worst, 0.04) << kind;
  }
}

TEST(ProceduralActions, JumpsFlyOnABallisticArcWithBothFeetOffTheFloor) {
  const Skeleton s = build_humanoid();
  ProceduralSpec spec = spec_of("jumps", 6.0);
  spec.jumps = {3, 0.5, 0.2};
  const Motion m = generate_procedural(spec, s, 240);
  const FootTrack track = humanoid_feet(s, m);
  int airborne = 0, flights = 0;
  double worst_gravity_error = 0;
  bool was_up = false;
  for (size_t f = 1; f + 1 < m.frames.size(); ++f) {
    double low = INFINITY;
    for (const auto& foot : track.frames[f]) {
      for (const auto& p : foot) low = std::min(low, p.y());
    }
    const bool up = low > 0.005;
    flights += up && !was_up;
    was_up = up;
    if (!up) continue;
    ++airborne;
    // In the air the pelvis falls freely.
    const double a = (m.frames[f + 1].root_position - 2 * m.frames[f].root_position +
                      m.frames[f - 1].root_position)
                         .y() *
                     m.fps * m.fps;
    worst_gravity_error = std::max(worst_gravity_error, std::abs(a + 9.81));
  }
  EXPECT_EQ(flights, 3);
  // About 2 sqrt(2 h / g) = 0.40 s of flight each.
  EXPECT_NEAR(airborne / m.fps / 3, 0.40, 0.08);
  EXPECT_LT(worst_gravity_error, 0.01);
  // Three jumps of 0.5 m forward, ending where they started across.
  const Eigen::Vector3d travel = m.frames.back().root_position - m.frames.front().root_position;
  EXPECT_NEAR(travel.z(), 1.5, 1e-6);
  EXPECT_NEAR(travel.x(), 0.0, 1e-6);
}

TEST(ProceduralActions, SquatsGoDownAsDeepAsAskedAndBendForwardReachesTheFloor) {
  for (const double height : {1.5, 2.0}) {
    const Skeleton s = build_humanoid({.height = height, .proportions = {}});
    ProceduralSpec squat = spec_of("squat", 4.0);
    squat.squat = {2, 0.35};
    const Motion m = generate_procedural(squat, s, 30);
    double lowest = INFINITY;
    for (const Pose& p : m.frames) lowest = std::min(lowest, p.root_position.y());
    const double hip = s[s.require("l_hip")].center.y();
    const double drop = (m.frames.front().root_position.y() - lowest) / hip;
    EXPECT_NEAR(drop, 0.35, 0.02) << height;

    const Motion bend = generate_procedural(spec_of("bend_forward", 5.0), s, 30);
    const int tips[2] = {s.require("l_hand_tip"), s.require("r_hand_tip")};
    double reach = INFINITY;
    for (const Pose& p : bend.frames) {
      const auto w = joint_positions(s, p);
      reach = std::min({reach, w[tips[0]].y(), w[tips[1]].y()});
    }
    EXPECT_NEAR(reach, 0.01 * height, 0.005) << height;
  }
}

TEST(ProceduralActions, KicksReachTheirHeightWithEachLeg) {
  const Skeleton s = build_humanoid();
  ProceduralSpec spec = spec_of("kick", 4.0);
  spec.kick = {2, 0.7};
  const Motion m = generate_procedural(spec, s, 60);
  const int ankle[2] = {s.require("l_talocrural"), s.require("r_talocrural")};
  double highest[2] = {0, 0};
  for (const Pose& p : m.frames) {
    const auto w = joint_positions(s, p);
    for (int side = 0; side < 2; ++side)
      highest[side] = std::max(highest[side], w[ankle[side]].y());
  }
  const double target = 0.7 * s[s.require("l_hip")].center.y();
  for (int side = 0; side < 2; ++side) EXPECT_NEAR(highest[side], target, 0.03) << side;
}

TEST(ProceduralActions, ArmsCrossInFrontOfTheChestWithoutTouching) {
  const Skeleton s = build_humanoid();
  const Motion m = generate_procedural(spec_of("arms_cross", 4.0), s, 60);
  const int elbow[2] = {s.require("l_elbow"), s.require("r_elbow")};
  const int wrist[2] = {s.require("l_radiocarpal"), s.require("r_radiocarpal")};
  const int chest = s.require("vt6");
  int crossed = 0;
  double closest = INFINITY;
  for (const Pose& p : m.frames) {
    const auto w = joint_positions(s, p);
    if (w[wrist[0]].x() < 0 && w[wrist[1]].x() > 0) {
      ++crossed;
      EXPECT_GT(w[wrist[0]].z(), w[chest].z() + 0.2);  // in front of the chest
    }
    // Closest approach of the forearms (segments, sampled).
    for (int i = 0; i <= 20; ++i) {
      for (int k = 0; k <= 20; ++k) {
        const Eigen::Vector3d a = w[elbow[0]] + i / 20.0 * (w[wrist[0]] - w[elbow[0]]);
        const Eigen::Vector3d b = w[elbow[1]] + k / 20.0 * (w[wrist[1]] - w[elbow[1]]);
        closest = std::min(closest, (a - b).norm());
      }
    }
  }
  EXPECT_GT(crossed, 10);
  // Forearms are 0.165 H round (body_mesh.cpp): 9 cm thick at 1.75 m; 12 cm at girth 1.3.
  EXPECT_GT(closest, 0.07 * 1.75);
}

TEST(ProceduralActions, SideStepsTravelSidewaysWithTheTrailingLegCrossing) {
  const Skeleton s = build_humanoid();
  for (const double distance : {1.2, -1.2}) {
    ProceduralSpec spec = spec_of("side_steps", 6.0);
    spec.side_steps = {2, distance};
    const Motion m = generate_procedural(spec, s, 30);
    const Eigen::Vector3d travel = m.frames.back().root_position - m.frames.front().root_position;
    // The last step crosses in front: the pelvis stands between the crossed feet.
    EXPECT_NEAR(travel.x(), distance, 0.15) << distance;
    EXPECT_NEAR(travel.z(), 0.0, 0.1) << distance;
    // The trailing ankle passes the leading one sideways.
    const int lead = s.require(distance > 0 ? "l_talocrural" : "r_talocrural");
    const int trail = s.require(distance > 0 ? "r_talocrural" : "l_talocrural");
    int crossed = 0;
    for (const Pose& p : m.frames) {
      const auto w = joint_positions(s, p);
      crossed += (w[trail].x() - w[lead].x()) * distance > 0;
    }
    EXPECT_GT(crossed, 20) << distance;
  }
}

TEST(ProceduralActions, TurnaroundComesBackFacingTheOtherWay) {
  const Skeleton s = build_humanoid();
  ProceduralSpec spec = spec_of("turnaround", 8.0);
  spec.speed_m_s = 1.0;
  spec.turnaround.distance_m = 2.0;
  const Motion m = generate_procedural(spec, s, 30);
  const int root = s.require("humanoid_root");
  double furthest = 0;
  for (const Pose& p : m.frames) furthest = std::max(furthest, p.root_position.z());
  // 2 m out, then the turn's own curve beyond.
  EXPECT_GT(furthest, 2.0);
  EXPECT_LT(furthest, 3.0);
  // Back past the start: 8 s in all less 2 s out and the turn's 3.1 s leave 2.9 s at 1 m/s.
  EXPECT_LT(m.frames.back().root_position.z(), 0.0);
  const Eigen::Vector3d forward = m.frames.back().rotations[root] * Eigen::Vector3d::UnitZ();
  EXPECT_LT(forward.z(), -0.95);
}

TEST(ProceduralActions, ArmSwingsReachTheirAmplitudeAtTheirFrequency) {
  const Skeleton s = build_humanoid();
  ProceduralSpec spec = spec_of("arm_swings", 5.0);
  spec.arm_swings = {2.0, 80};
  const Motion m = generate_procedural(spec, s, 120);
  const int shoulder = s.require("l_shoulder"), elbow = s.require("l_elbow");
  double front = 0;
  int crossings = 0;
  double last = 0;
  for (const Pose& p : m.frames) {
    const auto w = joint_positions(s, p);
    const Eigen::Vector3d arm = (w[elbow] - w[shoulder]).normalized();
    const double angle = std::atan2(arm.z(), -arm.y());  // forward of hanging
    front = std::max(front, angle);
    crossings += (angle > 0.1) != (last > 0.1);
    last = angle;
  }
  EXPECT_NEAR(front * 180 / kPi, 80, 3);
  // Two swings a second for 4.5 s, the first and last fading: about 2 * 8 threshold crossings.
  EXPECT_GE(crossings, 14);
  EXPECT_LE(crossings, 18);
}

TEST(ProceduralActions, BadParametersNameTheirKey) {
  const Skeleton s = build_humanoid();
  struct Bad {
    std::string kind, key;
    std::function<void(ProceduralSpec&)> set;
  };
  const std::vector<Bad> bad = {
      {"jumps", "count", [](ProceduralSpec& p) { p.jumps.count = 0; }},
      {"jumps", "distance", [](ProceduralSpec& p) { p.jumps.distance_m = 1.5; }},
      {"jumps", "height", [](ProceduralSpec& p) { p.jumps.height_m = 0.01; }},
      {"jumps", "duration", [](ProceduralSpec& p) { p.jumps.count = 8; }},
      {"turnaround", "distance", [](ProceduralSpec& p) { p.turnaround.distance_m = 0; }},
      {"turnaround", "duration", [](ProceduralSpec& p) { p.turnaround.distance_m = 6; }},
      {"squat", "depth", [](ProceduralSpec& p) { p.squat.depth = 0.6; }},
      {"squat", "count", [](ProceduralSpec& p) { p.squat.count = 21; }},
      {"arms_cross", "duration", [](ProceduralSpec& p) { p.arms_cross.count = 20; }},
      {"side_steps", "distance", [](ProceduralSpec& p) { p.side_steps.distance_m = 0.2; }},
      {"side_steps", "count", [](ProceduralSpec& p) { p.side_steps.count = 11; }},
      {"bend_forward", "duration", [](ProceduralSpec& p) { p.bend_forward.count = 4; }},
      {"kick", "height", [](ProceduralSpec& p) { p.kick.height = 1.2; }},
      {"arm_swings", "frequency", [](ProceduralSpec& p) { p.arm_swings.frequency_hz = 4; }},
      {"arm_swings", "amplitude", [](ProceduralSpec& p) { p.arm_swings.amplitude_deg = 170; }},
      {"turnaround", "speed", [](ProceduralSpec& p) { p.speed_m_s = 2.5; }},
  };
  for (const Bad& b : bad) {
    ProceduralSpec spec = spec_of(b.kind, 6.0);
    EXPECT_FALSE(procedural::parameter_problem(spec)) << b.kind;
    b.set(spec);
    const auto problem = procedural::parameter_problem(spec);
    ASSERT_TRUE(problem) << b.kind << " " << b.key;
    EXPECT_EQ(problem->key, b.key) << b.kind << ": " << problem->message;
    try {
      generate_procedural(spec, s, 30);
      ADD_FAILURE() << b.kind << " " << b.key;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(b.key), std::string::npos) << e.what();
    }
  }
  // Every action starts and ends standing still, so even its shortest clip needs its rests.
  EXPECT_TRUE(procedural::parameter_problem(spec_of("squat", 0.4)));
}

}  // namespace
}  // namespace simcap
