#include "core/effector_track.h"

#include "core/csv.h"

namespace simcap {

std::vector<EffectorSample> read_effector_track(const std::filesystem::path& path) {
  CsvReader csv(path, kEffectors2dColumns);
  std::vector<EffectorSample> out;
  while (csv.next()) {
    EffectorSample s;
    const long frame = csv.integer(0);
    if (frame < 0) csv.fail(0, "frame numbers start at 0");
    s.frame = static_cast<int>(frame);
    s.camera = csv.text(1);
    s.effector = csv.text(2);
    s.joint = csv.text(3);
    if (s.joint.empty()) csv.fail(3, "empty joint name");
    s.u = csv.number(4);
    s.v = csv.number(5);
    const std::string& state = csv.text(8);
    if (state != "tracking" && state != "occluded" && state != "lost") {
      csv.fail(8, "unknown state '" + state + "'; expected tracking, occluded or lost");
    }
    s.lost = state == "lost";
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace simcap
