// Calibration as a Blender Python script that builds the rig's cameras (focal length, principal
// point as lens shift, pose), so a user can look through simcap's cameras in Blender.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/camera.h"

namespace simcap {

// The script defines CAMERAS, a list of dicts (name, width, height, lens and sensor_width in mm,
// sensor_fit "HORIZONTAL", shift_x, shift_y, pixel_aspect_x, pixel_aspect_y, matrix_world as
// 4x4 rows, distortion), and build(bpy), which adds the cameras to a "simcap cameras"
// collection and sets the scene's resolution from the first camera; run as a script it calls
// build. Blender's camera model, for a point (x, y, z) in the camera object's frame (looking
// down -Z, +Y up), with f = lens / sensor_width * width and ycor = pixel_aspect_y /
// pixel_aspect_x: column = width / 2 + f x / -z - shift_x * width, row (from the top) =
// height / 2 - (f / ycor) y / -z + shift_y * width / ycor, pixel centres at +0.5; so
// shift_x = ((width - 1) / 2 - cx) / width, shift_y = (cy - (height - 1) / 2) ycor / width, and
// the pixel aspect carries fy / fx. Blender has no lens distortion: it is listed, not applied.
// Blender's world is +Z up: simcap's (x, y, z) becomes Blender's (x, -z, y).
std::string blender_camera_script(const std::vector<Camera>& cams);
// Writes blender_camera_script() to `path` atomically.
void write_blender_cameras(const std::filesystem::path& path, const std::vector<Camera>& cams);

}  // namespace simcap
