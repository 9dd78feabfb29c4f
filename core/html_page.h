// The common frame of simcap's HTML reports (validation, 2D keypoints, gestures): the page start
// with its style sheet, table rows, numbers and embedded images; plots come from svg_plot.h.
#pragma once

#include <string>
#include <vector>

#include "core/svg_plot.h"

namespace simcap {

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
