#include "validate/report_folder.h"

#include <string>

#include "core/error.h"

namespace simcap {

namespace fs = std::filesystem;

void check_report_folder(const fs::path& out) {
  if (!fs::exists(out)) return;
  if (!fs::is_directory(out)) {
    throw Error(out.string() + ": exists and is not a folder (expected a report folder)");
  }
  for (const char* own : {"meta.json", "gt", "calibration", "joints3d.csv"}) {
    if (fs::exists(out / own)) {
      throw Error(out.string() + ": holds a " +
                  (std::string(own) == "joints3d.csv" ? "track" : "dataset") + " (" + own +
                  "); write the report to a folder of its own");
    }
  }
}

}  // namespace simcap
