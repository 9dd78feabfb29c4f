// The detector keypoint layouts: their published orders and sizes, mirror partners that pair
// up, COCO's sigmas, and ground-truth points that exist on simcap's humanoid and on Joe.
#include <gtest/gtest.h>

#include <set>

#include "models/body_source.h"
#include "models/keypoint_layouts.h"
#include "models/keypoint_sets.h"
#include "models/x3d_humanoid.h"

namespace simcap {
namespace {

TEST(KeypointLayouts, SizesOrderAndLookup) {
  EXPECT_EQ(keypoint_layout(KeypointLayoutId::coco17).size(), 17);
  EXPECT_EQ(keypoint_layout(KeypointLayoutId::body25).size(), 25);
  EXPECT_EQ(keypoint_layout(KeypointLayoutId::blazepose33).size(), 33);
  EXPECT_EQ(keypoint_layout(KeypointLayoutId::h36m17).size(), 17);
  for (const auto& [name, id] : kKeypointLayouts) {
    EXPECT_EQ(keypoint_layout(id).id, id);
    EXPECT_NE(name_of(kKeypointLayouts, id), "?");
  }
  // Spot checks against the published orders (OpenPose doc/02_output.md, MediaPipe Pose's
  // landmark list, Human3.6M's 17-joint subset).
  const KeypointLayout& body25 = keypoint_layout(KeypointLayoutId::body25);
  EXPECT_EQ(body25.index("Neck"), 1);
  EXPECT_EQ(body25.index("MidHip"), 8);
  EXPECT_EQ(body25.index("LBigToe"), 19);
  EXPECT_EQ(body25.index("RHeel"), 24);
  const KeypointLayout& blaze = keypoint_layout(KeypointLayoutId::blazepose33);
  EXPECT_EQ(blaze.index("left_shoulder"), 11);
  EXPECT_EQ(blaze.index("right_thumb"), 22);
  EXPECT_EQ(blaze.index("left_hip"), 23);
  EXPECT_EQ(blaze.index("right_foot_index"), 32);
  EXPECT_EQ(keypoint_layout(KeypointLayoutId::h36m17).index("Thorax"), 8);
  EXPECT_EQ(keypoint_layout(KeypointLayoutId::coco17).index("right_ankle"), 16);
  EXPECT_EQ(blaze.index("no_such_point"), -1);
  EXPECT_EQ(layout_of_count(25), KeypointLayoutId::body25);
  EXPECT_EQ(layout_of_count(17), KeypointLayoutId::coco17);
  EXPECT_EQ(layout_of_count(18), std::nullopt);
}

TEST(KeypointLayouts, PartnersPairLeftWithRight) {
  const std::map<KeypointLayoutId, int> pairs = {{KeypointLayoutId::coco17, 8},
                                                 {KeypointLayoutId::body25, 11},
                                                 {KeypointLayoutId::blazepose33, 16},
                                                 {KeypointLayoutId::h36m17, 6}};
  for (const auto& [id, expected] : pairs) {
    const KeypointLayout& l = keypoint_layout(id);
    int paired = 0;
    for (int k = 0; k < l.size(); ++k) {
      const int p = l.keypoints[k].partner;
      if (p < 0) continue;
      ++paired;
      EXPECT_NE(p, k);
      EXPECT_EQ(l.keypoints[p].partner, k) << l.keypoints[k].name;
      // Partners are the same kind of point and, where COCO has it, have the same sigma.
      EXPECT_EQ(l.keypoints[p].truth, l.keypoints[k].truth) << l.keypoints[k].name;
      EXPECT_EQ(l.keypoints[p].sigma, l.keypoints[k].sigma) << l.keypoints[k].name;
    }
    EXPECT_EQ(paired, 2 * expected) << l.title;
  }
}

TEST(KeypointLayouts, CocoSigmas) {
  // pycocotools: [.26, .25, .25, .35, .35, .79, .79, .72, .72, .62, .62, 1.07, 1.07, .87, .87,
  // .89, .89] / 10.
  const std::vector<double> expected = {.26, .25, .25,  .35,  .35, .79, .79, .72, .72,
                                        .62, .62, 1.07, 1.07, .87, .87, .89, .89};
  const KeypointLayout& coco = keypoint_layout(KeypointLayoutId::coco17);
  for (int k = 0; k < 17; ++k) EXPECT_DOUBLE_EQ(coco.keypoints[k].sigma, expected[k] / 10);
  // Other layouts take the sigma of the COCO keypoint that is the same point, else 0.
  for (const auto& [name, id] : kKeypointLayouts) {
    for (const LayoutKeypoint& k : keypoint_layout(id).keypoints) {
      if (k.coco_twin.empty()) {
        EXPECT_EQ(k.sigma, 0.0) << k.name;
      } else {
        EXPECT_EQ(k.sigma, coco.keypoints[coco.index(k.coco_twin)].sigma) << k.name;
      }
    }
  }
  const KeypointLayout& body25 = keypoint_layout(KeypointLayoutId::body25);
  EXPECT_DOUBLE_EQ(body25.keypoints[body25.index("LHip")].sigma, 0.107);
  EXPECT_EQ(body25.keypoints[body25.index("Neck")].sigma, 0.0);
}

TEST(KeypointLayouts, TruthPointsExistOnSimcapBodies) {
  for (const Body& body :
       {build_body({}), read_x3d_humanoid(SIMCAP_SOURCE_DIR "/models/assets/JoeSkin.x3d")}) {
    std::set<std::string> coco, h36m;
    for (const BodyPoint& p : coco17_points(body.skeleton, body.mesh)) coco.insert(p.name);
    for (const BodyPoint& p : h36m17_points(body.skeleton, body.mesh)) h36m.insert(p.name);
    for (const auto& [name, id] : kKeypointLayouts) {
      int with_truth = 0;
      for (const LayoutKeypoint& k : keypoint_layout(id).keypoints) {
        const std::string t(k.truth_name);
        switch (k.truth) {
          case TruthKind::none:
            EXPECT_TRUE(t.empty()) << k.name;
            continue;
          case TruthKind::hanim_joint:
            EXPECT_GE(body.skeleton.find(t), 0) << k.name;
            EXPECT_FALSE(body.skeleton[body.skeleton.find(t)].is_site) << k.name;
            break;
          case TruthKind::coco17_point:
            EXPECT_TRUE(coco.count(t)) << k.name;
            break;
          case TruthKind::h36m17_point:
            EXPECT_TRUE(h36m.count(t)) << k.name;
            break;
        }
        ++with_truth;
      }
      // BODY_25: all but the neck and the six foot points; BlazePose: 17 of 33.
      const std::map<KeypointLayoutId, int> expected = {{KeypointLayoutId::coco17, 17},
                                                        {KeypointLayoutId::body25, 18},
                                                        {KeypointLayoutId::blazepose33, 17},
                                                        {KeypointLayoutId::h36m17, 17}};
      EXPECT_EQ(with_truth, expected.at(id)) << name;
    }
  }
}

}  // namespace
}  // namespace simcap
