// Detector output in: COCO keypoint results, OpenPose folders and the CSV, each as its tools
// write it and broken in the ways files break; COCO results out and back.
#include <gtest/gtest.h>

#include "core/atomic_file.h"
#include "models/detections.h"
#include "tests/support/error_of.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

using testing::error_of;

const std::vector<std::string> kCameras = {"cam00", "cam01", "cam02"};
constexpr int kFrames = 5;

// K keypoints x, y, score: keypoint k at (10 k + offset, 20 k + offset), score 0.5.
std::string triples(int k, double offset) {
  std::string s;
  for (int i = 0; i < k; ++i) {
    s += (i ? "," : "") + std::to_string(10 * i + offset) + "," + std::to_string(20 * i + offset) +
         ",0.5";
  }
  return "[" + s + "]";
}

TEST(Detections, CocoResultsByImageIdAndFileName) {
  testing::TempDir dir;
  // As MMPose writes them: image_id, category_id, keypoints, score; and one by file name.
  write_text_atomic(dir / "det.json",
                    "[{\"image_id\": 1, \"category_id\": 1, \"keypoints\": " + triples(17, 0) +
                        ", \"score\": 0.9},"
                        "{\"image_id\": 8, \"category_id\": 1, \"keypoints\": " +
                        triples(17, 1) +
                        ", \"score\": 0.8},"
                        "{\"file_name\": \"out/ds/cam01/rgb/000002.png\", \"keypoints\": " +
                        triples(17, 2) + "}]");
  const Detections d = read_detections(dir / "det.json", kCameras, kFrames);
  EXPECT_EQ(d.layout(), KeypointLayoutId::coco17);
  EXPECT_EQ(d.people(), 3);
  ASSERT_EQ(d.at(0, 0).size(), 1u);
  EXPECT_DOUBLE_EQ(d.at(0, 0)[0].score, 0.9);
  // image_id 8 = 1 + 2 * 3 + 1: frame 2, camera 1; the file name is the same image.
  ASSERT_EQ(d.at(2, 1).size(), 2u);
  EXPECT_DOUBLE_EQ(d.at(2, 1)[0].keypoints[3].x, 31);
  EXPECT_DOUBLE_EQ(d.at(2, 1)[0].keypoints[3].y, 61);
  EXPECT_DOUBLE_EQ(d.at(2, 1)[1].keypoints[16].y, 322);
  EXPECT_DOUBLE_EQ(d.at(2, 1)[1].score, 0.5);  // no score: the mean keypoint score
  // The same 17 points read as Human3.6M's when told.
  EXPECT_EQ(
      read_coco_results(dir / "det.json", kCameras, kFrames, KeypointLayoutId::h36m17).layout(),
      KeypointLayoutId::h36m17);
}

TEST(Detections, CocoResultsLayoutFromTheCount) {
  testing::TempDir dir;
  write_text_atomic(dir / "bp.json",
                    "[{\"image_id\": 3, \"keypoints\": " + triples(33, 0) + ", \"score\": 1}]");
  EXPECT_EQ(read_coco_results(dir / "bp.json", kCameras, kFrames).layout(),
            KeypointLayoutId::blazepose33);
  write_text_atomic(dir / "empty.json", "[]");
  EXPECT_EQ(read_coco_results(dir / "empty.json", kCameras, kFrames).people(), 0);
}

TEST(Detections, CocoResultsWrittenAndReadBack) {
  testing::TempDir dir;
  Detections d(KeypointLayoutId::blazepose33, kCameras, kFrames);
  for (int f = 0; f < kFrames; ++f) {
    for (int c = 0; c < 3; ++c) {
      for (int p = 0; p < (f + c) % 3; ++p) {
        DetectedPerson person{std::vector<DetectedKeypoint>(33), 0.25 * p + 0.125};
        for (int k = 0; k < 33; ++k) person.keypoints[k] = {f + 0.5 * k, c - 0.25 * k, 0.03125 * p};
        d.at(f, c).push_back(person);
      }
    }
  }
  write_coco_results(d, dir / "out.json");
  const Detections back = read_detections(dir / "out.json", kCameras, kFrames);
  EXPECT_EQ(back.layout(), KeypointLayoutId::blazepose33);
  ASSERT_EQ(back.people(), d.people());
  for (int f = 0; f < kFrames; ++f) {
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(back.at(f, c).size(), d.at(f, c).size());
      for (size_t p = 0; p < d.at(f, c).size(); ++p) {
        EXPECT_EQ(back.at(f, c)[p].score, d.at(f, c)[p].score);
        for (int k = 0; k < 33; ++k) {
          EXPECT_EQ(back.at(f, c)[p].keypoints[k].x, d.at(f, c)[p].keypoints[k].x);
          EXPECT_EQ(back.at(f, c)[p].keypoints[k].y, d.at(f, c)[p].keypoints[k].y);
          EXPECT_EQ(back.at(f, c)[p].keypoints[k].score, d.at(f, c)[p].keypoints[k].score);
        }
      }
    }
  }
}

TEST(Detections, CocoResultsBadFiles) {
  testing::TempDir dir;
  const auto error = [&](const std::string& text) {
    write_text_atomic(dir / "det.json", text);
    return error_of([&] { read_coco_results(dir / "det.json", kCameras, kFrames); });
  };
  const std::string file = (dir / "det.json").string();
  std::string short_list = triples(17, 0);
  short_list = short_list.substr(0, short_list.rfind(',')) + "]";
  EXPECT_EQ(error("[{\"image_id\": 1, \"keypoints\": " + triples(17, 0) +
                  "}, {\"image_id\": 2, \"keypoints\": " + short_list + "}]"),
            file + ": [1].keypoints: expected 51 numbers (17 keypoints x 3), got 50");
  EXPECT_EQ(error("[{\"image_id\": 16, \"keypoints\": " + triples(17, 0) + "}]"),
            file +
                ": [0].image_id: 16 is not an image of this dataset (1 + frame x 3 + camera, "
                "frames 0..4)");
  EXPECT_EQ(error("[{\"file_name\": \"cam07/rgb/000001.png\", \"keypoints\": []}]"),
            file +
                ": [0].file_name: \"cam07/rgb/000001.png\" is not <camera>/rgb/<frame>.png of "
                "a camera (cam00, cam01, cam02) and frame 0..4 of this dataset");
  EXPECT_EQ(error("[{\"image_id\": 1, \"keypoints\": [1, 2, 3, 4, 5, 6]}]"),
            file +
                ": [0].keypoints: 6 numbers are not x, y, score for 17 (coco17, h36m17), 25 "
                "(body25) or 33 (blazepose33) keypoints");
  std::string word_first = triples(17, 0);
  word_first.replace(1, word_first.find(',') - 1, "\"a\"");
  EXPECT_EQ(error("[{\"image_id\": 1, \"keypoints\": " + word_first + "}]"),
            file + ": [0].keypoints[0]: expected a number, got string");
  EXPECT_EQ(error("[{\"image_id\": 1, \"category_id\": 2, \"keypoints\": []}]"),
            file + ": [0].category_id: expected 1 (person)");
  EXPECT_EQ(error("[{\"keypoints\": []}]"),
            file + ": [0]: expected an integer image_id or a string file_name");
  EXPECT_EQ(error("{\"annotations\": []}"),
            file + ": expected COCO keypoint results: an array of detections");
  EXPECT_NE(error("[{\"image_id\": 1,").find(file + ": not valid JSON: "), std::string::npos);
  EXPECT_EQ(error_of([&] {
              read_coco_results(dir / "missing.json", kCameras, kFrames);
            }).find((dir / "missing.json").string()),
            0u);
}

// OpenPose 1.7's --write_json output for one image (one person, empty face and hands).
std::string openpose_file(const std::vector<std::string>& people) {
  std::string list;
  for (const std::string& p : people) {
    list += (list.empty() ? "" : ",") + std::string("{\"person_id\":[-1],\"pose_keypoints_2d\":") +
            p +
            ",\"face_keypoints_2d\":[],\"hand_left_keypoints_2d\":[],"
            "\"hand_right_keypoints_2d\":[],\"pose_keypoints_3d\":[],\"face_keypoints_3d\":[],"
            "\"hand_left_keypoints_3d\":[],\"hand_right_keypoints_3d\":[]}";
  }
  return "{\"version\":1.3,\"people\":[" + list + "]}";
}

TEST(Detections, OpenPoseFolder) {
  testing::TempDir dir;
  const auto op = dir / "openpose";
  std::string undetected_neck = triples(25, 0);
  undetected_neck.replace(undetected_neck.find(",10.000000,20.000000,0.5"), 24, ",0,0,0");
  write_text_atomic(op / "cam00" / "000003_keypoints.json",
                    openpose_file({triples(25, 0), undetected_neck}));
  // Run on a video, OpenPose numbers the frames with 12 digits after the video's name.
  write_text_atomic(op / "cam02" / "walk_000000000004_keypoints.json", openpose_file({}));
  write_text_atomic(op / "cam02" / "walk_000000000001_keypoints.json",
                    openpose_file({triples(25, 5)}));
  std::filesystem::create_directories(op / "cam01");
  write_text_atomic(op / "cam01" / "notes.txt", "not a detection");
  const Detections d = read_detections(op, kCameras, kFrames);
  EXPECT_EQ(d.layout(), KeypointLayoutId::body25);
  EXPECT_EQ(d.people(), 3);
  ASSERT_EQ(d.at(3, 0).size(), 2u);
  EXPECT_DOUBLE_EQ(d.at(3, 0)[0].score, 0.5);
  EXPECT_EQ(d.at(3, 0)[1].keypoints[1].score, 0.0);
  EXPECT_DOUBLE_EQ(d.at(1, 2)[0].keypoints[24].x, 245);
  EXPECT_TRUE(d.at(4, 2).empty());
}

TEST(Detections, OpenPoseBadFolders) {
  testing::TempDir dir;
  const auto op = dir / "openpose";
  for (const auto& c : kCameras) std::filesystem::create_directories(op / c);
  const auto error = [&] { return error_of([&] { read_openpose_folder(op, kCameras, kFrames); }); };
  write_text_atomic(op / "cam01" / "000009_keypoints.json", openpose_file({}));
  EXPECT_EQ(error(),
            (op / "cam01" / "000009_keypoints.json").string() +
                ": the name is not <frame>_keypoints.json for a frame 0..4 of this dataset");
  std::filesystem::remove(op / "cam01" / "000009_keypoints.json");
  write_text_atomic(op / "cam01" / "000000_keypoints.json", openpose_file({"[1,2,0.5]"}));
  EXPECT_EQ(error(), (op / "cam01" / "000000_keypoints.json").string() +
                         ": people[0].pose_keypoints_2d: 3 numbers are not x, y, score for 17 "
                         "(coco17, h36m17), 25 (body25) or 33 (blazepose33) keypoints");
  write_text_atomic(op / "cam01" / "000000_keypoints.json", "{\"version\":1.3}");
  EXPECT_EQ(error(), (op / "cam01" / "000000_keypoints.json").string() +
                         ": people: expected an array of people");
  std::filesystem::remove(op / "cam01" / "000000_keypoints.json");
  std::filesystem::remove_all(op / "cam02");
  EXPECT_EQ(error(), (op / "cam02").string() +
                         ": no such folder: OpenPose detections need one folder per camera");
}

TEST(Detections, CsvLayoutFromTheNames) {
  testing::TempDir dir;
  write_text_atomic(dir / "det.csv",
                    "frame,camera,person,keypoint,x,y,score\n"
                    "0,cam01,7,left_wrist,10.5,20.25,0.75\n"
                    "0,cam01,7,nose,1,2,0.25\n"
                    "0,cam01,2,nose,3,4,1\n"
                    "4,cam02,0,right_ankle,5,6,0\n");
  const Detections coco = read_detections(dir / "det.csv", kCameras, kFrames);
  EXPECT_EQ(coco.layout(), KeypointLayoutId::coco17);
  ASSERT_EQ(coco.at(0, 1).size(), 2u);
  // People in ascending id order: 2, then 7.
  EXPECT_DOUBLE_EQ(coco.at(0, 1)[0].keypoints[0].x, 3);
  EXPECT_DOUBLE_EQ(coco.at(0, 1)[1].keypoints[9].y, 20.25);
  EXPECT_DOUBLE_EQ(coco.at(0, 1)[1].score, 0.5);
  EXPECT_EQ(coco.at(0, 1)[1].keypoints[1].score, 0.0);
  EXPECT_EQ(coco.at(4, 2)[0].score, 0.0);
  // A BlazePose-only name makes it BlazePose-33.
  write_text_atomic(dir / "bp.csv",
                    "frame,camera,person,keypoint,x,y,score\n0,cam00,0,left_wrist,1,2,1\n"
                    "0,cam00,0,left_heel,1,2,1\n");
  EXPECT_EQ(read_detections(dir / "bp.csv", kCameras, kFrames).layout(),
            KeypointLayoutId::blazepose33);
}

TEST(Detections, CsvBadFiles) {
  testing::TempDir dir;
  const std::string file = (dir / "det.csv").string();
  const auto error = [&](const std::string& rows,
                         std::optional<KeypointLayoutId> layout = std::nullopt) {
    write_text_atomic(dir / "det.csv", "frame,camera,person,keypoint,x,y,score\n" + rows);
    return error_of([&] { read_detections_csv(dir / "det.csv", kCameras, kFrames, layout); });
  };
  EXPECT_EQ(error("0,cam00,0,nose,1,2,1\n0,cam00,0,nose,1,2,1\n"),
            file + ":3: column 'keypoint': a second row for nose of this person in this image");
  EXPECT_EQ(error("0,cam00,0,Neck,1,2,1\n0,cam00,0,nose,1,2,1\n"),
            file +
                ": column 'keypoint': the names are not all of one layout (coco17, body25, "
                "blazepose33 or h36m17; see validate/README.md)");
  EXPECT_EQ(error("0,cam00,0,Neck,1,2,1\n", KeypointLayoutId::coco17),
            file + ":2: column 'keypoint': \"Neck\" is not a keypoint of COCO-17");
  EXPECT_EQ(error("5,cam00,0,nose,1,2,1\n"), file + ":2: column 'frame': expected a frame 0..4");
  EXPECT_EQ(error("0,cam9,0,nose,1,2,1\n"),
            file + ":2: column 'camera': \"cam9\" is not a camera of the dataset");
  EXPECT_EQ(error("0,cam00,-1,nose,1,2,1\n"),
            file + ":2: column 'person': expected a person id >= 0");
  EXPECT_NE(error("0,cam00,0,nose,1,x,1\n").find(file + ":2: column 'y'"), std::string::npos);
}

}  // namespace
}  // namespace simcap
