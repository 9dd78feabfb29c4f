// The report.html of `simcap validate`: one self-contained page (inline SVG plots, overlay
// images embedded as base64 JPEG) that shows the metrics, where the errors are, and why.
#pragma once

#include <string>
#include <vector>

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

// The start of a report page in the reports' common style: doctype, head with `title`, the
// style sheet, <body> and the <h1>; the caller appends the body and "</body>\n</html>\n".
std::string report_page_start(const std::string& title);
// One <tr> of `cells` (HTML already), each in <td> or the given tag.
std::string html_row(const std::vector<std::string>& cells, const char* tag = "td");
// A number by printf `format`; a dash for NaN (an empty group).
std::string html_number(const char* format, double v);

// Standard base64 (RFC 4648) with padding, for data: URIs.
std::string base64_encode(const std::vector<unsigned char>& bytes);

}  // namespace simcap
