// The reports' shared frame: escaping, numbers, base64 against RFC 4648's vectors, axis ticks and
// a line plot that is well-formed SVG with its gaps kept.
#include <gtest/gtest.h>

#include <cmath>
#include <pugixml.hpp>

#include "core/html_page.h"

namespace simcap {
namespace {

std::vector<unsigned char> bytes(const std::string& s) {
  return {s.begin(), s.end()};
}

TEST(HtmlPage, EscapesNumbersAndBase64) {
  EXPECT_EQ(xml_escape("a<b & \"c\" 'd'>"), "a&lt;b &amp; &quot;c&quot; &#39;d&#39;&gt;");
  EXPECT_EQ(html_number("%.1f", 2.25), "2.2");
  EXPECT_EQ(html_number("%.1f", std::nan("")), "&ndash;");
  EXPECT_EQ(html_row({"a", "b"}, "th"), "<tr><th>a</th><th>b</th></tr>\n");
  // RFC 4648 §10.
  EXPECT_EQ(base64_encode(bytes("")), "");
  EXPECT_EQ(base64_encode(bytes("f")), "Zg==");
  EXPECT_EQ(base64_encode(bytes("fo")), "Zm8=");
  EXPECT_EQ(base64_encode(bytes("foo")), "Zm9v");
  EXPECT_EQ(base64_encode(bytes("foobar")), "Zm9vYmFy");
  const std::string page = report_page_start("R & D");
  EXPECT_NE(page.find("<title>R &amp; D</title>"), std::string::npos);
}

TEST(SvgPlot, TicksAndAWellFormedPlotWithAGap) {
  EXPECT_EQ(nice_ticks(0, 10, 5), (std::vector<double>{0, 2, 4, 6, 8, 10}));
  LinePlot plot;
  plot.title = "a < b";
  plot.series = {{"s", {0, 1, 2, 3}, {1, 2, std::nan(""), 4}}};
  plot.reference_y = 3;
  const std::string svg = line_plot_svg(plot);
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(svg.c_str())) << svg;
  EXPECT_STREQ(doc.first_child().name(), "svg");
  EXPECT_NE(svg.find("a &lt; b"), std::string::npos);
}

}  // namespace
}  // namespace simcap
