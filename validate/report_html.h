// The report.html of `simcap validate`: one self-contained page (inline SVG plots, overlay
// images embedded as base64 JPEG) that shows the metrics, where the errors are, and why.
#pragma once

#include <string>
#include <vector>

#include "core/html_page.h"
#include "validate/evaluation.h"

namespace simcap {

struct OverlayImage {
  int frame = 0;
  std::string camera;
  std::string reason;               // why this frame was picked ("worst frame", ...)
  std::vector<unsigned char> jpeg;  // encoded image
};

struct ReportContent {
  std::string dataset, track;  // as the user named them
  std::vector<OverlayImage> overlays;
  std::string video_file;  // relative to the report; empty when there is no video
  std::string video_note;  // what the video shows, or why there is none
};

std::string report_html(const Evaluation& ev, const ReportContent& content);

}  // namespace simcap
