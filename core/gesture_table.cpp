#include "core/gesture_table.h"

#include "core/csv.h"

namespace simcap {

std::vector<GestureInterval> read_gesture_table(const std::filesystem::path& path) {
  CsvReader csv(path, kGesturesColumns);
  std::vector<GestureInterval> out;
  while (csv.next()) {
    GestureInterval g;
    g.actor = csv.text(0);
    g.limb = csv.text(1);
    if (g.limb.empty()) csv.fail(1, "empty limb");
    g.kind = csv.text(2);
    if (g.kind != "dynamic" && g.kind != "static") {
      csv.fail(2, "expected dynamic or static, got '" + g.kind + "'");
    }
    g.label = csv.text(3);
    if (g.label.empty()) csv.fail(3, "empty label");
    g.first_frame = static_cast<int>(csv.integer(4));
    g.last_frame = static_cast<int>(csv.integer(5));
    if (g.first_frame < 0) csv.fail(4, "frame numbers start at 0");
    if (g.last_frame < g.first_frame) csv.fail(5, "expected a frame >= first_frame");
    out.push_back(std::move(g));
  }
  return out;
}

}  // namespace simcap
