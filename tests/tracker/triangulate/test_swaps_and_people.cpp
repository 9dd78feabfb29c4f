// Left/right swaps in a single view and the choice of the actor among several detected people,
// on exact projections of a known pose: what was planted must be found, nothing else.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <random>

#include "rig.h"
#include "tracker/triangulate/person_association.h"
#include "tracker/triangulate/pose_triangulator.h"

namespace simcap::tracker {
namespace {

using testing::camera_ring;

// A standing person's keypoints: 0 nose, 1/2 left/right shoulder, 3/4 left/right knee,
// 5/6 left/right wrist; `at` shifts the whole body on the floor.
std::vector<Eigen::Vector3d> body(const Eigen::Vector3d& at = Eigen::Vector3d::Zero()) {
  std::vector<Eigen::Vector3d> p = {{0, 1.65, 0.08},    {0.18, 1.42, 0},  {-0.18, 1.42, 0},
                                    {0.10, 0.50, 0.03}, {-0.10, 0.50, 0}, {0.25, 0.85, 0.05},
                                    {-0.25, 0.85, 0.0}};
  for (auto& q : p) q += at;
  return p;
}
const std::vector<int> kPartner = {-1, 2, 1, 4, 3, 6, 5};

PersonKeypoints seen(const Camera& c, const std::vector<Eigen::Vector3d>& points,
                     std::mt19937* rng = nullptr) {
  std::normal_distribution<double> noise(0.0, 2.0);
  PersonKeypoints person;
  for (const auto& x : points) {
    Eigen::Vector2d p = *c.project(x);
    if (rng) p += Eigen::Vector2d(noise(*rng), noise(*rng));
    person.keypoints.emplace_back(p.x(), p.y(), 0.9);
  }
  return person;
}

TEST(PoseTriangulation, RepairsALeftRightSwapInOneView) {
  const auto cams = camera_ring(4);
  const auto truth = body();
  for (int wrong = 0; wrong < 4; ++wrong) {
    for (int pair : {1, 3, 5}) {
      std::vector<PersonKeypoints> people;
      for (const Camera& c : cams) people.push_back(seen(c, truth));
      std::swap(people[wrong].keypoints[pair], people[wrong].keypoints[pair + 1]);
      std::vector<const PersonKeypoints*> views;
      for (const auto& p : people) views.push_back(&p);
      const TriangulatedPose pose = triangulate_pose(cams, views, kPartner, 7);
      ASSERT_EQ(pose.swaps.size(), 1u) << "camera " << wrong << " pair " << pair;
      EXPECT_EQ(pose.swaps[0].camera, wrong);
      EXPECT_EQ(pose.swaps[0].keypoint, pair);
      for (int k = 0; k < 7; ++k) {
        ASSERT_TRUE(pose.keypoints[k]);
        EXPECT_LT((pose.keypoints[k]->position - truth[k]).norm(), 1e-9);
        EXPECT_EQ(pose.keypoints[k]->excluded, 0) << "the repaired view is used, not dropped";
      }
    }
  }
}

TEST(PoseTriangulation, LeavesAgreeingViewsAlone) {
  const auto cams = camera_ring(4);
  const auto truth = body();
  std::mt19937 rng(5);
  std::vector<PersonKeypoints> people;
  for (const Camera& c : cams) people.push_back(seen(c, truth, &rng));
  std::vector<const PersonKeypoints*> views;
  for (const auto& p : people) views.push_back(&p);
  views[2] = nullptr;  // one camera did not find the person
  const TriangulatedPose pose = triangulate_pose(cams, views, kPartner, 7);
  EXPECT_TRUE(pose.swaps.empty());
  for (int k = 0; k < 7; ++k) {
    ASSERT_TRUE(pose.keypoints[k]);
    EXPECT_EQ(pose.keypoints[k]->views, 0b1011u);
    EXPECT_LT((pose.keypoints[k]->position - truth[k]).norm(), 0.06);  // 2 px ~ 14 mm a view
  }
}

TEST(PoseTriangulation, LendsNoViewsToAKeypointOneCameraAloneSaw) {
  // The right wrist found in camera 0 only: it stays missing, and no view of the left wrist is
  // relabelled to give it a second one.
  const auto cams = camera_ring(4);
  const auto truth = body();
  std::vector<PersonKeypoints> people;
  for (const Camera& c : cams) people.push_back(seen(c, truth));
  for (int c = 1; c < 4; ++c) people[c].keypoints[6].z() = 0.0;
  std::vector<const PersonKeypoints*> views;
  for (const auto& p : people) views.push_back(&p);
  const TriangulatedPose pose = triangulate_pose(cams, views, kPartner, 7);
  EXPECT_TRUE(pose.swaps.empty());
  EXPECT_FALSE(pose.keypoints[6]);
  ASSERT_TRUE(pose.keypoints[5]);
  EXPECT_LT((pose.keypoints[5]->position - truth[5]).norm(), 1e-9);
}

TEST(PersonAssociation, FindsTheSamePersonInEveryCameraAndFollowsIt) {
  const auto cams = camera_ring(4);
  const auto actor = body({0.4, 0, 0.2}), other = body({-0.6, 0, -0.5});
  // The other person stands nearer most cameras (looks more prominent) in some views; the
  // order of the detections differs per camera.
  std::vector<std::vector<PersonKeypoints>> people(4);
  for (int c = 0; c < 4; ++c) {
    if (c % 2) {
      people[c] = {seen(cams[c], actor), seen(cams[c], other)};
    } else {
      people[c] = {seen(cams[c], other), seen(cams[c], actor)};
    }
  }
  const Association seeded = associate_people(cams, people, {});
  // Seeding picks one person consistently: either all actor or all other.
  const bool picked_actor = seeded.person[0] == 1;
  for (int c = 0; c < 4; ++c) {
    EXPECT_EQ(seeded.person[c], (c % 2 == 1) == picked_actor ? 0 : 1) << "camera " << c;
    EXPECT_LT(seeded.cost[c], 1e-6);
  }
  EXPECT_EQ(std::count(seeded.kind.begin(), seeded.kind.end(), AssociationKind::seeded), 1);
  // Expected where the actor was a moment ago (3 cm away): the actor is chosen everywhere.
  std::vector<Eigen::Vector3d> moved = actor;
  for (auto& x : moved) x += Eigen::Vector3d(0.03, 0, 0);
  std::vector<PersonKeypoints> expected;
  for (const Camera& c : cams) expected.push_back(seen(c, moved));
  const Association followed = associate_people(cams, people, expected);
  for (int c = 0; c < 4; ++c) {
    EXPECT_EQ(followed.person[c], c % 2 ? 0 : 1) << "camera " << c;
    EXPECT_EQ(followed.kind[c], AssociationKind::tracked);
  }
  // A camera that lost the actor joins the others through triangulation; one without the
  // actor chooses nobody rather than the other person.
  expected[1].keypoints.clear();
  people[3] = {seen(cams[3], other)};
  const Association rejoined = associate_people(cams, people, expected);
  EXPECT_EQ(rejoined.person[1], 0);
  EXPECT_EQ(rejoined.kind[1], AssociationKind::joined);
  EXPECT_EQ(rejoined.person[3], -1);
}

}  // namespace
}  // namespace simcap::tracker
