#include "core/blender_cameras.h"

#include <algorithm>

#include "core/atomic_file.h"
#include "core/literal_text.h"

namespace simcap {
namespace {

// Every Blender camera uses a 36 mm wide sensor (Blender's default); only lens / sensor matters.
constexpr double kSensorWidthMm = 36.0;

std::string py_list(std::initializer_list<double> values) {
  std::string out = "[";
  for (const double v : values) out += (out.size() > 1 ? ", " : "") + float_text(v);
  return out + "]";
}

}  // namespace

std::string blender_camera_script(const std::vector<Camera>& cams) {
  // simcap world (+Y up) -> Blender world (+Z up); OpenCV camera axes -> Blender's (y, z flipped).
  Eigen::Matrix3d to_blender;
  to_blender << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  const Eigen::Matrix3d flip = Eigen::Vector3d(1, -1, -1).asDiagonal();
  std::string table;
  for (const Camera& cam : cams) {
    const double w = cam.width, h = cam.height;
    const double fx = cam.K(0, 0), fy = cam.K(1, 1);
    const double aspect_x = std::max(1.0, fy / fx), aspect_y = std::max(1.0, fx / fy);
    const double ycor = aspect_y / aspect_x;
    Eigen::Matrix4d world = Eigen::Matrix4d::Identity();
    world.topLeftCorner<3, 3>() = to_blender * cam.R.transpose() * flip;
    world.topRightCorner<3, 1>() = to_blender * cam.centre();
    table += "    {\"name\": " + quoted_text(cam.name) +
             ", \"width\": " + std::to_string(cam.width) +
             ", \"height\": " + std::to_string(cam.height) +
             ",\n     \"lens\": " + float_text(fx * kSensorWidthMm / w) +
             ", \"sensor_width\": " + float_text(kSensorWidthMm) +
             ", \"sensor_fit\": \"HORIZONTAL\",\n     \"shift_x\": " +
             float_text(((w - 1) / 2 - cam.K(0, 2)) / w) +
             ", \"shift_y\": " + float_text((cam.K(1, 2) - (h - 1) / 2) * ycor / w) +
             ",\n     \"pixel_aspect_x\": " + float_text(aspect_x) +
             ", \"pixel_aspect_y\": " + float_text(aspect_y) + ",\n     \"matrix_world\": [";
    for (int r = 0; r < 4; ++r) {
      table += (r ? ", " : "") + py_list({world(r, 0), world(r, 1), world(r, 2), world(r, 3)});
    }
    table += "],\n     \"distortion\": " +
             py_list({cam.dist[0], cam.dist[1], cam.dist[2], cam.dist[3], cam.dist[4]}) + "},\n";
  }
  return "# The cameras of a simcap rig for Blender (2.8 or later), written by simcap.\n"
         "# Run: blender --python blender_cameras.py, or open it in Blender's Text Editor and\n"
         "# press Run Script. simcap's world (+Y up) appears turned to Blender's +Z up:\n"
         "# simcap (x, y, z) is Blender (x, -z, y). Each camera reproduces simcap's pinhole\n"
         "# (focal length, principal point as lens shift, pixel aspect for fy / fx); Blender\n"
         "# cameras have no lens distortion, so `distortion` (OpenCV k1 k2 p1 p2 k3) is not\n"
         "# applied. The scene's render resolution is the first camera's; lens shift is relative\n"
         "# to the width, so render each camera at its own width and height.\n"
         "CAMERAS = [\n" +
         table +
         "]\n\n\n"
         "def build(bpy):\n"
         "    import mathutils\n"
         "    scene = bpy.context.scene\n"
         "    collection = bpy.data.collections.new(\"simcap cameras\")\n"
         "    scene.collection.children.link(collection)\n"
         "    objects = []\n"
         "    for c in CAMERAS:\n"
         "        data = bpy.data.cameras.new(c[\"name\"])\n"
         "        data.sensor_fit = c[\"sensor_fit\"]\n"
         "        data.sensor_width = c[\"sensor_width\"]\n"
         "        data.lens = c[\"lens\"]\n"
         "        data.shift_x = c[\"shift_x\"]\n"
         "        data.shift_y = c[\"shift_y\"]\n"
         "        data.clip_start = 0.01\n"
         "        data.clip_end = 1000.0\n"
         "        obj = bpy.data.objects.new(c[\"name\"], data)\n"
         "        obj.matrix_world = mathutils.Matrix(c[\"matrix_world\"])\n"
         "        collection.objects.link(obj)\n"
         "        objects.append(obj)\n"
         "    if CAMERAS:\n"
         "        first = CAMERAS[0]\n"
         "        scene.render.resolution_x = first[\"width\"]\n"
         "        scene.render.resolution_y = first[\"height\"]\n"
         "        scene.render.resolution_percentage = 100\n"
         "        scene.render.pixel_aspect_x = first[\"pixel_aspect_x\"]\n"
         "        scene.render.pixel_aspect_y = first[\"pixel_aspect_y\"]\n"
         "        scene.camera = objects[0]\n"
         "    return objects\n\n\n"
         "if __name__ == \"__main__\":\n"
         "    import bpy\n"
         "    build(bpy)\n";
}

void write_blender_cameras(const std::filesystem::path& path, const std::vector<Camera>& cams) {
  write_text_atomic(path, blender_camera_script(cams));
}

}  // namespace simcap
