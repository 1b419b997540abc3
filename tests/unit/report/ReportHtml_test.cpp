#include "report/ReportHtml.hpp"

#include <gtest/gtest.h>

#include "report/ReportAssets.hpp"

namespace unimap::report {
namespace {

std::size_t Count(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (std::size_t pos = text.find(needle); pos != std::string::npos; pos = text.find(needle, pos + 1)) ++n;
  return n;
}

TEST(ReportHtmlTest, InlinesEveryScriptAndLoadsNothingFromElsewhere) {
  const std::string html = RenderReportHtml({{"title", "a <b> & c"}});
  EXPECT_EQ(Count(html, "<script>"), 5u);  // three.js, OrbitControls, dygraphs, viewer, report
  EXPECT_EQ(Count(html, "<script src"), 0u);
  EXPECT_EQ(Count(html, "<link"), 0u);
  EXPECT_EQ(Count(html, "sourceMappingURL"), 0u);
  EXPECT_NE(html.find("<title>a &lt;b&gt; &amp; c</title>"), std::string::npos);
  EXPECT_NE(html.find(std::string(EmbeddedAssets().three_js.substr(0, 200))), std::string::npos);
  EXPECT_NE(html.find("OrbitControls"), std::string::npos);
  EXPECT_NE(html.find("Dygraph"), std::string::npos);
  EXPECT_EQ(html.rfind("</html>\n"), html.size() - 8);
}

TEST(ReportHtmlTest, DataCannotEndItsScriptElement) {
  const std::string html = RenderReportHtml({{"title", "x"}, {"folder", "</script><script>alert(1)//"}});
  EXPECT_EQ(html.find("</script><script>alert"), std::string::npos);
  EXPECT_NE(html.find("\\u003c/script>\\u003cscript>alert(1)//"), std::string::npos);
}

}  // namespace
}  // namespace unimap::report
