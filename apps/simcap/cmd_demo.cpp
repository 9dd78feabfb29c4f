#include <cstdio>
#include <filesystem>

#include "apps/simcap/commands.h"
#include "core/calibration.h"
#include "core/rig.h"

namespace simcap::cli {
namespace {

// Until the renderer exists, the demo builds the default studio rig and writes its calibration:
// the most complete pipeline simcap has so far. It says so rather than pretending.
int run_demo(const std::filesystem::path& out) {
  const auto cams = corner_rig(4.0, 4.0, 2.5, 0.1, {0, 1.0, 0}, ImageSpec{});
  write_opencv_calibration(out / "calibration" / "opencv.yaml", cams);
  write_easymocap_calibration(out / "calibration" / "intri.yml", out / "calibration" / "extri.yml",
                              cams);
  std::printf("simcap demo: rendering, tracking and validation are not built yet.\n");
  std::printf("What ran: the default 4-camera studio rig (4x4 m room, VGA, cameras in the upper\n");
  std::printf("corners at 2.5 m) was built and its calibration written to %s/calibration\n",
              out.string().c_str());
  std::printf("(OpenCV opencv.yaml and EasyMocap intri.yml/extri.yml).\n");
  for (const auto& c : cams) {
    const auto px = c.project({0, 1.0, 0});
    std::printf(
        "  %s at (%.2f, %.2f, %.2f) m sees the room centre at 1 m height at pixel (%.1f, %.1f)\n",
        c.name.c_str(), c.centre().x(), c.centre().y(), c.centre().z(), px->x(), px->y());
  }
  return 0;
}

}  // namespace

void add_demo(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("demo", "Run the closed loop on the built-in default scene");
  static std::string out = "out/demo";
  cmd->add_option("-o,--output", out, "Output folder")->capture_default_str();
  cmd->footer("Example:\n  simcap demo -o out/demo");
  cmd->callback([&action] { action = [] { return run_demo(out); }; });
}

}  // namespace simcap::cli
