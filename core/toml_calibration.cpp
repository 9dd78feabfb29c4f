#include "core/toml_calibration.h"

#include "core/atomic_file.h"
#include "core/calibration.h"
#include "core/literal_text.h"

namespace simcap {
namespace {

template <class Vector>
std::string array(const Vector& v) {
  std::string out = "[";
  for (Eigen::Index i = 0; i < v.size(); ++i) out += (i ? ", " : "") + float_text(v[i]);
  return out + "]";
}

}  // namespace

std::string toml_calibration(const std::vector<Camera>& cams) {
  std::string out;
  for (size_t c = 0; c < cams.size(); ++c) {
    const Camera& cam = cams[c];
    const Eigen::Vector3d r = rodrigues_of(cam.R);
    out += "[cam_" + std::to_string(c) + "]\n";
    out += "name = " + quoted_text(cam.name) + "\n";
    out += "size = [" + std::to_string(cam.width) + ", " + std::to_string(cam.height) + "]\n";
    out += "matrix = [" + array(Eigen::Vector3d(cam.K.row(0).transpose())) + ", " +
           array(Eigen::Vector3d(cam.K.row(1).transpose())) + ", " +
           array(Eigen::Vector3d(cam.K.row(2).transpose())) + "]\n";
    out += "distortions = " + array(cam.dist) + "\n";
    out += "rotation = " + array(r) + "\n";
    out += "translation = " + array(cam.t) + "\n";
    out += "fisheye = false\n\n";
  }
  out += "[metadata]\nadjusted = false\nerror = 0.0\n";
  return out;
}

void write_toml_calibration(const std::filesystem::path& path, const std::vector<Camera>& cams) {
  write_text_atomic(path, toml_calibration(cams));
}

}  // namespace simcap
