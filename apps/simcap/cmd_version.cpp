#include <OpenImageIO/imageio.h>
#include <assimp/version.h>
#include <embree3/rtcore.h>
#include <oneapi/tbb/version.h>
#include <CLI/Version.hpp>
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <opencv2/core/utility.hpp>
#include <pugixml.hpp>

#include <cstdio>
#include <string>

#include "apps/simcap/commands.h"

namespace simcap::cli {
namespace {

// Embree reports the version of the library it actually loaded through a device property.
std::string embree_runtime_version() {
  RTCDevice device = rtcNewDevice("threads=1");
  if (!device) return "unavailable";
  const long v = static_cast<long>(rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION));
  rtcReleaseDevice(device);
  return std::to_string(v / 10000) + "." + std::to_string(v / 100 % 100) + "." +
         std::to_string(v % 100);
}

int print_versions() {
  std::printf("simcap       %s\n", SIMCAP_VERSION);
  std::printf("Embree       %s (built against %s)\n", embree_runtime_version().c_str(),
              RTC_VERSION_STRING);
  std::printf("OpenImageIO  %d.%d.%d (built against %s)\n", OIIO::openimageio_version() / 10000,
              OIIO::openimageio_version() / 100 % 100, OIIO::openimageio_version() % 100,
              OIIO_VERSION_STRING);
  std::printf("Assimp       %u.%u.%u\n", aiGetVersionMajor(), aiGetVersionMinor(),
              aiGetVersionPatch());
  std::printf("OpenCV       %s\n", cv::getVersionString().c_str());
  std::printf("Eigen        %d.%d.%d\n", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION,
              EIGEN_MINOR_VERSION);
  // urdfdom has no version macro or call; this is the version pkg-config reported at build time.
  std::printf("urdfdom      %s (pkg-config)\n", SIMCAP_URDFDOM_VERSION);
  std::printf("oneTBB       %s (built against %s)\n", TBB_runtime_version(), TBB_VERSION_STRING);
  std::printf("nlohmann     %d.%d.%d\n", NLOHMANN_JSON_VERSION_MAJOR, NLOHMANN_JSON_VERSION_MINOR,
              NLOHMANN_JSON_VERSION_PATCH);
  std::printf("pugixml      %d.%d\n", PUGIXML_VERSION / 1000, PUGIXML_VERSION / 10 % 100);
  std::printf("CLI11        %s\n", CLI11_VERSION);
  return 0;
}

}  // namespace

void add_version(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "version", "Print simcap's version and the versions of the libraries it was built against");
  cmd->footer("Example:\n  simcap version");
  cmd->callback([&action] { action = print_versions; });
}

}  // namespace simcap::cli
