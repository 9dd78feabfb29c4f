// Resampling: slerp for rotations, linear for the root, the duration kept.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "models/resample.h"

namespace simcap {
namespace {

// Joint 0 turns about a fixed axis at a constant rate and the root moves at constant velocity,
// so the exact pose at any time is known.
const Eigen::Vector3d kAxis = Eigen::Vector3d(1, 2, -0.5).normalized();
constexpr double kRate = 3.0;  // rad/s
const Eigen::Vector3d kVelocity(0.4, -0.1, 1.3);

Eigen::Quaterniond exact_rotation(double t) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(kRate * t, kAxis));
}

Motion uniform_motion(double fps, int frames) {
  Motion m;
  m.fps = fps;
  for (int i = 0; i < frames; ++i) {
    Pose p;
    p.root_position = kVelocity * (i / fps);
    p.rotations = {exact_rotation(i / fps), Eigen::Quaterniond::Identity()};
    // The same rotation written with the other sign every other frame: slerp must take the
    // short way anyway.
    if (i % 2) p.rotations[0].coeffs() *= -1;
    m.frames.push_back(p);
  }
  return m;
}

TEST(Resample, SlerpsRotationsAndInterpolatesTheRootLinearly) {
  const Motion source = uniform_motion(120.0, 241);  // 2 s
  for (double fps : {30.0, 50.0, 24.0, 200.0}) {
    const Motion out = resample_motion(source, fps);
    EXPECT_DOUBLE_EQ(out.fps, fps);
    EXPECT_EQ(out.frames.size(), static_cast<size_t>(std::floor(2.0 * fps + 1e-9)) + 1);
    for (size_t i = 0; i < out.frames.size(); ++i) {
      const double t = i / fps;
      EXPECT_LT(out.frames[i].rotations[0].angularDistance(exact_rotation(t)), 1e-9) << fps;
      EXPECT_LT((out.frames[i].root_position - kVelocity * t).norm(), 1e-12) << fps;
      EXPECT_LT(out.frames[i].rotations[1].angularDistance(Eigen::Quaterniond::Identity()), 1e-12);
    }
  }
}

TEST(Resample, DividingRatesPickSourceFramesAndTheDurationIsKept) {
  const Motion source = uniform_motion(120.0, 994);
  const Motion out = resample_motion(source, 30.0);
  ASSERT_EQ(out.frames.size(), 249u);  // 993 / 4 = 248.25 frame intervals
  for (size_t i = 0; i < out.frames.size(); ++i) {
    EXPECT_LT(out.frames[i].rotations[0].angularDistance(source.frames[4 * i].rotations[0]), 1e-12);
  }
  const Motion same = resample_motion(source, 120.0);
  EXPECT_EQ(same.frames.size(), source.frames.size());
  EXPECT_LE(out.duration_s(), source.duration_s());
  const Motion single = resample_motion(uniform_motion(10.0, 1), 30.0);
  EXPECT_EQ(single.frames.size(), 1u);
}

TEST(Resample, BadInputIsAnError) {
  EXPECT_THROW(resample_motion(uniform_motion(120.0, 10), 0.0), Error);
  EXPECT_THROW(resample_motion(uniform_motion(120.0, 10), -30.0), Error);
  EXPECT_THROW(resample_motion(Motion{}, 30.0), Error);
  Motion broken = uniform_motion(120.0, 10);
  broken.frames[5].rotations.pop_back();
  EXPECT_THROW(resample_motion(broken, 50.0), Error);
}

// Three frames an hour apart (a few bytes of X3D can say so) resampled to 30 frames/s: 216001
// frames, within the frame limit; of 200 joints they are more rotations than simcap keeps.
TEST(Resample, MoreJointRotationsThanTheLimitAreRefusedBeforeAllocating) {
  Motion m;
  m.fps = 1.0 / 3600;
  Pose p;
  p.rotations.assign(200, Eigen::Quaterniond::Identity());
  m.frames.assign(3, p);
  try {
    resample_motion(m, 30.0);
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "resample: the motion: 216001 frames of 200 joints are more joint rotations than "
                 "simcap keeps in memory, 33554432");
  }
  m.frames[0].rotations.resize(100);
  for (Pose& f : m.frames) f.rotations.resize(100);
  EXPECT_EQ(resample_motion(m, 30.0).frames.size(), 216001u);
}

}  // namespace
}  // namespace simcap
