// Calibration exports read by independent readers: the TOML by Python's tomllib, the COLMAP
// model by a parser and camera model written here from COLMAP's documentation, the Blender
// script's numbers through Blender's camera model (and by Blender itself when it is installed).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "core/atomic_file.h"
#include "core/blender_cameras.h"
#include "core/calibration.h"
#include "core/colmap_model.h"
#include "core/rig.h"
#include "core/toml_calibration.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

using Json = nlohmann::json;
using simcap::testing::TempDir;

// A ring of three cameras made unlike one another: the second with fx != fy and an off-centre
// principal point, the third portrait with all five distortion coefficients.
std::vector<Camera> varied_rig() {
  auto cams = ring_rig(3, {0, 1, 0}, 3.0, 2.0, ImageSpec{640, 480, 1.2});
  cams[1].K(1, 1) *= 1.07;
  cams[1].K(0, 2) = 301.25;
  cams[1].K(1, 2) = 250.75;
  cams[2].width = 480;
  cams[2].height = 640;
  cams[2].K(0, 2) = 239.5;
  cams[2].K(1, 2) = 319.5;
  cams[2].dist << -0.21, 0.06, 0.0012, -0.0018, 0.013;
  return cams;
}

// Points around the actor's space, in front of every ring camera.
std::vector<Eigen::Vector3d> sample_points() {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.8, 0.8);
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < 50; ++i) out.emplace_back(u(rng), 1.0 + u(rng), u(rng));
  return out;
}

bool have_program(const std::string& name) {
  return std::system(("command -v " + name + " >/dev/null 2>&1").c_str()) == 0;
}

// Standard output of a shell command; the test fails when it exits non-zero.
std::string run(const std::string& command) {
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, pipe)) > 0) out.append(buf, n);
  EXPECT_EQ(pclose(pipe), 0) << command << "\n" << out;
  return out;
}

TEST(TomlCalibration, PythonTomllibReadsEveryCamera) {
  if (!have_program("python3")) GTEST_SKIP() << "python3 is not installed";
  TempDir dir;
  const auto cams = varied_rig();
  const auto path = dir / "calibration.toml";
  write_toml_calibration(path, cams);
  const Json toml = Json::parse(
      run("python3 -c 'import json, sys, tomllib; print(json.dumps(tomllib.load(open(sys.argv[1], "
          "\"rb\"))))' " +
          path.string()));
  ASSERT_EQ(toml.size(), cams.size() + 1);
  EXPECT_EQ(toml["metadata"]["adjusted"], false);
  for (size_t c = 0; c < cams.size(); ++c) {
    const Camera& cam = cams[c];
    const Json& t = toml["cam_" + std::to_string(c)];
    EXPECT_EQ(t["name"], cam.name);
    EXPECT_EQ(t["size"], Json::array({cam.width, cam.height}));
    EXPECT_EQ(t["fisheye"], false);
    for (int r = 0; r < 3; ++r) {
      for (int k = 0; k < 3; ++k) EXPECT_EQ(t["matrix"][r][k].get<double>(), cam.K(r, k));
    }
    for (int k = 0; k < 5; ++k) EXPECT_EQ(t["distortions"][k].get<double>(), cam.dist[k]);
    // The Rodrigues vector turns back into the camera's rotation.
    const Eigen::Vector3d r(t["rotation"][0], t["rotation"][1], t["rotation"][2]);
    const Eigen::Matrix3d R = Eigen::AngleAxisd(r.norm(), r.normalized()).toRotationMatrix();
    EXPECT_LT((R - cam.R).norm(), 1e-12);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(t["translation"][k].get<double>(), cam.t[k]);
  }
  // Strict readers (Python's `toml`, used by Anipose and Pose2Sim) want arrays of one type:
  // every number in a float array carries a point or an exponent.
  std::istringstream lines(read_text(path));
  int arrays = 0;
  for (std::string line; std::getline(lines, line);) {
    const std::string key = line.substr(0, line.find(" = "));
    if (key != "matrix" && key != "distortions" && key != "rotation" && key != "translation") {
      continue;
    }
    ++arrays;
    std::string values = line.substr(line.find('=') + 1);
    for (char& c : values) {
      if (c == '[' || c == ']' || c == ',') c = ' ';
    }
    std::istringstream in(values);
    for (std::string v; in >> v;) EXPECT_NE(v.find_first_of(".e"), v.npos) << line;
  }
  EXPECT_EQ(arrays, 4 * static_cast<int>(cams.size()));
}

// COLMAP's text model and camera models, written from its documentation
// (https://colmap.github.io/format.html, "Camera models" of colmap/src/colmap/sensor/models.h).
struct ColmapCamera {
  std::string model;
  int width = 0, height = 0;
  std::vector<double> params;
};
struct ColmapImage {
  double qw, qx, qy, qz, tx, ty, tz;
  int camera_id;
  std::string name;
};

std::vector<std::string> data_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] == '#') continue;
    lines.push_back(line);
  }
  return lines;
}

std::map<int, ColmapCamera> parse_colmap_cameras(const std::string& text) {
  std::map<int, ColmapCamera> out;
  for (const std::string& line : data_lines(text)) {
    if (line.empty()) continue;
    std::istringstream in(line);
    int id;
    ColmapCamera c;
    in >> id >> c.model >> c.width >> c.height;
    for (double v; in >> v;) c.params.push_back(v);
    out[id] = c;
  }
  return out;
}

// Two lines per image; the second (2D points) is empty here.
std::vector<ColmapImage> parse_colmap_images(const std::string& text) {
  std::vector<ColmapImage> out;
  const auto lines = data_lines(text);
  for (size_t i = 0; i < lines.size(); i += 2) {
    std::istringstream in(lines[i]);
    int id;
    ColmapImage im;
    in >> id >> im.qw >> im.qx >> im.qy >> im.qz >> im.tx >> im.ty >> im.tz >> im.camera_id >>
        im.name;
    EXPECT_EQ(id, static_cast<int>(out.size()) + 1);
    EXPECT_TRUE(i + 1 >= lines.size() || lines[i + 1].empty());
    out.push_back(im);
  }
  return out;
}

// COLMAP's projection: world -> camera by the unit quaternion and translation, then the model.
Eigen::Vector2d colmap_project(const ColmapCamera& c, const ColmapImage& im,
                               const Eigen::Vector3d& X) {
  const double w = im.qw, x = im.qx, y = im.qy, z = im.qz;
  Eigen::Matrix3d R;
  R << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),  //
      2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),   //
      2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  const Eigen::Vector3d p = R * X + Eigen::Vector3d(im.tx, im.ty, im.tz);
  const double u = p.x() / p.z(), v = p.y() / p.z();
  const auto& k = c.params;  // fx fy cx cy k1 k2 p1 p2 [k3 k4 k5 k6]
  const double u2 = u * u, v2 = v * v, uv = u * v, r2 = u2 + v2;
  double radial;
  if (c.model == "OPENCV") {
    radial = 1 + k[4] * r2 + k[5] * r2 * r2;
  } else {
    EXPECT_EQ(c.model, "FULL_OPENCV");
    const double r4 = r2 * r2, r6 = r4 * r2;
    radial = (1 + k[4] * r2 + k[5] * r4 + k[8] * r6) / (1 + k[9] * r2 + k[10] * r4 + k[11] * r6);
  }
  const double ud = u * radial + 2 * k[6] * uv + k[7] * (r2 + 2 * u2);
  const double vd = v * radial + 2 * k[7] * uv + k[6] * (r2 + 2 * v2);
  return {k[0] * ud + k[2], k[1] * vd + k[3]};
}

TEST(ColmapModel, ProjectsLikeTheCamerasUnderColmapsConventions) {
  TempDir dir;
  const auto cams = varied_rig();
  const std::vector<std::string> names = {"cam00/rgb/000000.png", "cam01/rgb/000000.png",
                                          "cam02/rgb/000000.png"};
  write_colmap_model(dir / "colmap", cams, names);
  const auto cameras = parse_colmap_cameras(read_text(dir / "colmap" / "cameras.txt"));
  const auto images = parse_colmap_images(read_text(dir / "colmap" / "images.txt"));
  EXPECT_TRUE(data_lines(read_text(dir / "colmap" / "points3D.txt")).empty());
  ASSERT_EQ(cameras.size(), 3u);
  ASSERT_EQ(images.size(), 3u);
  EXPECT_EQ(cameras.at(1).model, "OPENCV");
  EXPECT_EQ(cameras.at(3).model, "FULL_OPENCV");  // k3 != 0
  for (size_t c = 0; c < cams.size(); ++c) {
    const ColmapImage& im = images[c];
    EXPECT_EQ(im.name, names[c]);
    const ColmapCamera& cc = cameras.at(im.camera_id);
    EXPECT_EQ(cc.width, cams[c].width);
    EXPECT_EQ(cc.height, cams[c].height);
    EXPECT_GE(im.qw, 0);
    for (const Eigen::Vector3d& X : sample_points()) {
      // COLMAP's pixel centres are at +0.5 of simcap's (OpenCV's).
      const Eigen::Vector2d expected = *cams[c].project(X) + Eigen::Vector2d(0.5, 0.5);
      EXPECT_LT((colmap_project(cc, im, X) - expected).norm(), 1e-9) << cams[c].name;
    }
  }
}

// Blender's camera model (source/blender/blenkernel/intern/camera.cc,
// BKE_camera_params_compute_viewplane, with sensor_fit HORIZONTAL): pixel of a world point.
Eigen::Vector2d blender_project(const Json& c, const Eigen::Vector3d& world_simcap) {
  Eigen::Matrix4d M;
  for (int r = 0; r < 4; ++r) {
    for (int k = 0; k < 4; ++k) M(r, k) = c["matrix_world"][r][k];
  }
  // Blender's world is +Z up.
  const Eigen::Vector3d wb(world_simcap.x(), -world_simcap.z(), world_simcap.y());
  const Eigen::Vector3d p = (M.inverse() * wb.homogeneous()).head<3>();
  const double w = c["width"], h = c["height"];
  const double f = c["lens"].get<double>() / c["sensor_width"].get<double>() * w;
  const double ycor = c["pixel_aspect_y"].get<double>() / c["pixel_aspect_x"].get<double>();
  const double column = w / 2 + f * p.x() / -p.z() - c["shift_x"].get<double>() * w;
  const double row = h / 2 - (f / ycor) * p.y() / -p.z() + c["shift_y"].get<double>() * w / ycor;
  return {column - 0.5, row - 0.5};  // Blender's pixel centres sit at +0.5
}

TEST(BlenderCameras, ScriptNumbersReproduceThePinholeInBlendersModel) {
  if (!have_program("python3")) GTEST_SKIP() << "python3 is not installed";
  TempDir dir;
  auto cams = varied_rig();
  cams[2].dist.setZero();  // Blender has no lens distortion
  const auto script = dir / "blender_cameras.py";
  write_blender_cameras(script, cams);
  // Python loads the module without Blender (build() needs bpy; the table does not).
  const Json table =
      Json::parse(run("python3 -c 'import importlib.util, json, sys; s = "
                      "importlib.util.spec_from_file_location(\"cams\", sys.argv[1]); m = "
                      "importlib.util.module_from_spec(s); s.loader.exec_module(m); "
                      "print(json.dumps(m.CAMERAS))' " +
                      script.string()));
  ASSERT_EQ(table.size(), cams.size());
  for (size_t c = 0; c < cams.size(); ++c) {
    EXPECT_EQ(table[c]["name"], cams[c].name);
    for (const Eigen::Vector3d& X : sample_points()) {
      EXPECT_LT((blender_project(table[c], X) - *cams[c].project(X)).norm(), 1e-9) << cams[c].name;
    }
  }
}

TEST(BlenderCameras, BlenderItselfSeesThePointsWhereSimcapDoes) {
  if (!have_program("blender")) {
    GTEST_SKIP() << "Blender is not installed (apt install blender to run this check)";
  }
  TempDir dir;
  auto cams = varied_rig();
  cams.resize(2);
  const auto script = dir / "blender_cameras.py";
  write_blender_cameras(script, cams);
  const auto points = sample_points();
  std::string pts = "[";
  for (const auto& X : points) {
    pts += "(" + std::to_string(X.x()) + "," + std::to_string(-X.z()) + "," +
           std::to_string(X.y()) + "),";
  }
  pts += "]";
  write_text_atomic(dir / "check.py",
                    "import bpy, json, runpy, sys\n"
                    "from bpy_extras.object_utils import world_to_camera_view\n"
                    "from mathutils import Vector\n"
                    "m = runpy.run_path(sys.argv[-1])\n"
                    "scene = bpy.context.scene\n"
                    "out = []\n"
                    "for obj, c in zip(m['build'](bpy), m['CAMERAS']):\n"
                    "    scene.render.resolution_x = c['width']\n"
                    "    scene.render.resolution_y = c['height']\n"
                    "    scene.render.pixel_aspect_x = c['pixel_aspect_x']\n"
                    "    scene.render.pixel_aspect_y = c['pixel_aspect_y']\n"
                    "    v = [world_to_camera_view(scene, obj, Vector(p)) for p in " +
                        pts +
                        "]\n"
                        "    out.append([[q.x * c['width'] - 0.5, (1 - q.y) * c['height'] - 0.5] "
                        "for q in v])\n"
                        "print('RESULT' + json.dumps(out))\n");
  const std::string out = run("blender -b --factory-startup --python " +
                              (dir / "check.py").string() + " -- " + script.string() + " 2>&1");
  const size_t at = out.find("RESULT");
  ASSERT_NE(at, out.npos) << out;
  const Json result = Json::parse(out.substr(at + 6, out.find('\n', at) - at - 6));
  for (size_t c = 0; c < cams.size(); ++c) {
    for (size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector2d b(result[c][i][0], result[c][i][1]);
      EXPECT_LT((b - *cams[c].project(points[i])).norm(), 1e-3) << cams[c].name;
    }
  }
}

}  // namespace
}  // namespace simcap
