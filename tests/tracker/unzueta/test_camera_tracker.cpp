// CameraTracker's re-finding of a lost hand on a synthetic person: a hand whose arm swings
// away faster than its flock can follow is lost, and after CameraTrackerParams::refind_patience
// frames it restarts on the far end of its skin blob reachable from the shoulder, and only
// within the arm's reach; and its correction from outside (multiview re-seeding, borrowed
// colours and swaps).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "tracker/unzueta/camera_tracker.h"

namespace simcap::tracker {
namespace {

constexpr double kPersonPx = 240;
const cv::Point kShoulder(120, 97);

struct Frame {
  cv::Mat bgr, silhouette;
};

// A frontal person on a grey floor: a skin head, a shirt torso and one arm (shirt sleeve, skin
// forearm and hand) hanging down (`raised` false) or held out sideways (true).
Frame person(bool raised) {
  cv::RNG rng(7);
  cv::Mat floor(320, 320, CV_8UC3), skin(320, 320, CV_8UC3), shirt(320, 320, CV_8UC3);
  rng.fill(floor, cv::RNG::UNIFORM, cv::Scalar(90, 90, 90), cv::Scalar(130, 130, 130));
  rng.fill(skin, cv::RNG::UNIFORM, cv::Scalar(60, 90, 170), cv::Scalar(100, 130, 230));
  rng.fill(shirt, cv::RNG::UNIFORM, cv::Scalar(120, 20, 20), cv::Scalar(200, 60, 60));
  for (cv::Mat* m : {&floor, &skin, &shirt}) cv::GaussianBlur(*m, *m, {5, 5}, 1.2);
  cv::Mat skin_mask(floor.size(), CV_8UC1, cv::Scalar(0)), shirt_mask = skin_mask.clone();
  cv::circle(skin_mask, {160, 40}, 18, 255, -1);
  cv::rectangle(shirt_mask, cv::Rect(120, 75, 80, 150), 255, -1);
  if (raised) {
    cv::rectangle(shirt_mask, cv::Rect(78, 90, 43, 15), 255, -1);
    cv::rectangle(skin_mask, cv::Rect(48, 91, 30, 13), 255, -1);
    cv::circle(skin_mask, {40, 97}, 10, 255, -1);
  } else {
    cv::rectangle(shirt_mask, cv::Rect(105, 90, 15, 50), 255, -1);
    cv::rectangle(skin_mask, cv::Rect(106, 140, 13, 45), 255, -1);
    cv::circle(skin_mask, {112, 192}, 10, 255, -1);
  }
  Frame f;
  f.bgr = floor.clone();
  shirt.copyTo(f.bgr, shirt_mask);
  skin.copyTo(f.bgr, skin_mask);
  f.silhouette = skin_mask | shirt_mask;
  return f;
}

// The first frame's regions: the head, and the right hand hanging.
InitialRegions head_and_hand() {
  InitialRegions regions;
  regions.person_px = kPersonPx;
  regions.roi[index_of(Effector::head)] = cv::Rect2d(136, 16, 48, 48);
  regions.roi[index_of(Effector::right_hand)] = cv::Rect2d(100, 180, 24, 24);
  return regions;
}

// Tracks 4 frames hanging, then the raised arm; returns the hand's state and position after
// each frame (index = frame - 1).
std::vector<std::pair<CfofState, cv::Point2d>> track_hand(const CameraTrackerParams& params,
                                                          int frames) {
  CameraTracker tracker(params);
  const Frame first = person(false);
  tracker.initialize(first.bgr, first.silhouette, head_and_hand());
  std::array<double, kEffectorCount> depth;
  depth.fill(std::numeric_limits<double>::quiet_NaN());
  std::array<std::optional<cv::Point2d>, kEffectorCount> root;
  root[index_of(Effector::head)] = cv::Point2d(160, 75);
  root[index_of(Effector::right_hand)] = cv::Point2d(kShoulder);
  std::vector<std::pair<CfofState, cv::Point2d>> out;
  for (int f = 1; f <= frames; ++f) {
    const Frame frame = person(f > 4);
    tracker.track(frame.bgr, frame.silhouette, depth, root);
    out.emplace_back(tracker.state(Effector::right_hand), tracker.position(Effector::right_hand));
  }
  return out;
}

double distance(cv::Point2d a, cv::Point2d b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

// Shoulder to fingertip in the body's proportions (CameraTrackerParams::refind_reach).
CameraTrackerParams refinding() {
  CameraTrackerParams params;
  params.refind_reach[index_of(Effector::left_hand)] = 0.44;
  params.refind_reach[index_of(Effector::right_hand)] = 0.44;
  return params;
}

TEST(CameraTracker, LostHandIsReFoundWhereItsArmEndsAfterThePatience) {
  const cv::Point2d hand(40, 97);
  const CameraTrackerParams params = refinding();
  const int frames = 4 + params.refind_patience + 5;
  const auto track = track_hand(params, frames);
  // Hanging, the hand is followed.
  for (int f = 1; f <= 4; ++f) {
    EXPECT_EQ(track[f - 1].first, CfofState::tracking) << "frame " << f;
    EXPECT_LT(distance(track[f - 1].second, {112, 192}), 10.0) << "frame " << f;
  }
  // The arm swings out: the hand's ROI shows no skin, and it is not tracked for the patience's
  // frames (the frame of the swing counts as the first).
  for (int f = 5; f < 4 + params.refind_patience; ++f) {
    EXPECT_NE(track[f - 1].first, CfofState::tracking) << "frame " << f;
    EXPECT_GT(distance(track[f - 1].second, hand), 50.0) << "frame " << f;
  }
  // Then it restarts on the hand, not on the forearm nor the head, and keeps it.
  for (int f = 4 + params.refind_patience; f <= frames; ++f) {
    EXPECT_EQ(track[f - 1].first, CfofState::tracking) << "frame " << f;
    EXPECT_LT(distance(track[f - 1].second, hand), 8.0) << "frame " << f;
  }
}

TEST(CameraTracker, WithoutReFindingTheLostHandStaysLost) {
  const CameraTrackerParams params;
  const auto track = track_hand(params, 4 + params.refind_patience + 5);
  EXPECT_NE(track.back().first, CfofState::tracking);
  EXPECT_GT(distance(track.back().second, {40, 97}), 50.0);
}

// The hand's reach bounds the search: a shorter arm (a reach that ends before the hand) finds
// nothing to restart on.
TEST(CameraTracker, HandBeyondTheArmsReachIsNotReFound) {
  CameraTrackerParams params = refinding();
  params.refind_reach[index_of(Effector::right_hand)] = 60 / kPersonPx;
  const auto track = track_hand(params, 4 + params.refind_patience + 5);
  EXPECT_NE(track.back().first, CfofState::tracking);
}

// A hand whose first ROI held none of the person learnt no colours: it stays lost, and the
// re-finding, which searches by them, passes it over (it used to throw in OpenCV's
// calcBackProject on the empty histogram: hop4 from cam02 with --refind-reach).
TEST(CameraTracker, HandWithoutColoursIsNotSearchedFor) {
  const CameraTrackerParams params = refinding();
  CameraTracker tracker(params);
  InitialRegions regions;
  regions.person_px = kPersonPx;
  regions.roi[index_of(Effector::head)] = cv::Rect2d(136, 16, 48, 48);
  regions.roi[index_of(Effector::left_hand)] = cv::Rect2d(260, 260, 24, 24);  // the floor
  const Frame hanging = person(false);
  tracker.initialize(hanging.bgr, hanging.silhouette, regions);
  ASSERT_EQ(tracker.state(Effector::left_hand), CfofState::lost);
  std::array<double, kEffectorCount> depth;
  depth.fill(std::numeric_limits<double>::quiet_NaN());
  std::array<std::optional<cv::Point2d>, kEffectorCount> root;
  root[index_of(Effector::left_hand)] = cv::Point2d(200, 97);
  for (int f = 0; f < params.refind_patience + 3; ++f) {
    ASSERT_NO_THROW(tracker.track(hanging.bgr, hanging.silhouette, depth, root)) << "frame " << f;
  }
  EXPECT_EQ(tracker.state(Effector::left_hand), CfofState::lost);
}

// Multiview re-seeding (CameraTracker::correct): the hand lost in the swing is moved to where
// the other cameras put it and is followed there; without the correction it is not.
TEST(CameraTracker, CorrectedHandIsFollowedWhereOtherCamerasPutIt) {
  const cv::Point2d hand(40, 97);
  for (bool corrected : {false, true}) {
    CameraTracker tracker;
    const Frame hanging = person(false), raised = person(true);
    tracker.initialize(hanging.bgr, hanging.silhouette, head_and_hand());
    std::array<double, kEffectorCount> depth;
    depth.fill(std::numeric_limits<double>::quiet_NaN());
    for (int f = 0; f < 3; ++f) tracker.track(raised.bgr, raised.silhouette, depth);
    ASSERT_NE(tracker.state(Effector::right_hand), CfofState::tracking);
    if (corrected) tracker.correct(Effector::right_hand, hand);
    for (int f = 0; f < 3; ++f) {
      tracker.track(raised.bgr, raised.silhouette, depth);
      // CFOF centres the flock on the hand and the wrist beside it.
      const bool on_hand = tracker.state(Effector::right_hand) == CfofState::tracking &&
                           distance(tracker.position(Effector::right_hand), hand) < 15.0;
      EXPECT_EQ(on_hand, corrected) << "frame " << f;
    }
    // A tracked part is moved by the correction.
    const cv::Point2d head = tracker.position(Effector::head) + cv::Point2d(10, 0);
    tracker.correct(Effector::head, head);
    EXPECT_LT(distance(tracker.position(Effector::head), head), 1e-9);
  }
}

// Multiview re-seeding of a part that learnt no colours (its first ROI lay on the floor): it
// cannot be restarted where the other cameras put it until it takes the colours another
// camera learnt for it (CameraTracker::borrow_colours), and is then followed there.
TEST(CameraTracker, APartWithoutColoursStartsOnColoursBorrowedFromAnotherCamera) {
  const Frame hanging = person(false);
  const InitialRegions seen = head_and_hand();
  CameraTracker donor;
  donor.initialize(hanging.bgr, hanging.silhouette, seen);
  ASSERT_EQ(donor.state(Effector::right_hand), CfofState::tracking);
  const cv::Point2d hand(112, 192);
  std::array<double, kEffectorCount> depth;
  depth.fill(std::numeric_limits<double>::quiet_NaN());
  for (bool borrowed : {false, true}) {
    InitialRegions blind = seen;
    blind.roi[index_of(Effector::right_hand)] = cv::Rect2d(260, 260, 24, 24);  // the floor
    CameraTracker tracker;
    tracker.initialize(hanging.bgr, hanging.silhouette, blind);
    ASSERT_EQ(tracker.state(Effector::right_hand), CfofState::lost);
    if (borrowed) tracker.borrow_colours(Effector::right_hand, donor, 1.0);
    tracker.correct(Effector::right_hand, hand);
    for (int f = 0; f < 3; ++f) {
      tracker.track(hanging.bgr, hanging.silhouette, depth);
      const bool on_hand = tracker.state(Effector::right_hand) == CfofState::tracking &&
                           distance(tracker.position(Effector::right_hand), hand) < 15.0;
      EXPECT_EQ(on_hand, borrowed) << "frame " << f;
    }
  }
  // A part with colours of its own keeps them: the donor's head is not the hand.
  CameraTracker own;
  own.initialize(hanging.bgr, hanging.silhouette, seen);
  own.borrow_colours(Effector::right_hand, donor, 3.0);
  EXPECT_EQ(own.roi(Effector::right_hand), donor.roi(Effector::right_hand));
}

// Multiview swap repair (CameraTracker::swap): a camera that started its left hand on the hand
// and its right hand on the head (labels exchanged) has the two tracks exchanged whole, and
// each part is then followed where the other was.
TEST(CameraTracker, SwappedPartsExchangeTheirTracks) {
  CameraTracker tracker;
  InitialRegions regions;
  regions.person_px = kPersonPx;
  regions.roi[index_of(Effector::left_hand)] = cv::Rect2d(100, 180, 24, 24);
  regions.roi[index_of(Effector::right_hand)] = cv::Rect2d(136, 16, 48, 48);
  const Frame hanging = person(false);
  tracker.initialize(hanging.bgr, hanging.silhouette, regions);
  const cv::Point2d hand = tracker.position(Effector::left_hand);
  const cv::Point2d head = tracker.position(Effector::right_hand);
  const cv::Rect2d hand_roi = tracker.roi(Effector::left_hand);
  tracker.swap(Effector::left_hand, Effector::right_hand);
  EXPECT_EQ(tracker.position(Effector::right_hand), hand);
  EXPECT_EQ(tracker.position(Effector::left_hand), head);
  EXPECT_EQ(tracker.roi(Effector::right_hand), hand_roi);
  std::array<double, kEffectorCount> depth;
  depth.fill(std::numeric_limits<double>::quiet_NaN());
  for (int f = 0; f < 3; ++f) {
    tracker.track(hanging.bgr, hanging.silhouette, depth);
    EXPECT_EQ(tracker.state(Effector::right_hand), CfofState::tracking);
    EXPECT_LT(distance(tracker.position(Effector::right_hand), hand), 5.0) << "frame " << f;
    EXPECT_LT(distance(tracker.position(Effector::left_hand), head), 5.0) << "frame " << f;
  }
}

}  // namespace
}  // namespace simcap::tracker
