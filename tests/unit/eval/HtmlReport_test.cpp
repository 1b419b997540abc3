#include "eval/HtmlReport.hpp"

#include <gtest/gtest.h>

#include "eval/Base64.hpp"

namespace unimap::eval {
namespace {

TEST(HtmlReportTest, EscapesMarkup) {
  EXPECT_EQ(EscapeHtml("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
}

TEST(HtmlReportTest, EmbedsEachFigureAsADataUri) {
  TrajectoryMetrics m;
  m.drift_percent = 1.5;
  const std::vector<Figure> figures = {{"one.png", "first", "abc"}, {"two.png", "second", "de"}};
  const std::string html = RenderHtmlReport(m, figures, {"e.tum", "t.tum"});
  EXPECT_NE(html.find("src=\"data:image/png;base64," + EncodeBase64("abc") + "\""), std::string::npos);
  EXPECT_NE(html.find("src=\"data:image/png;base64," + EncodeBase64("de") + "\""), std::string::npos);
  EXPECT_NE(html.find("1.5000"), std::string::npos);
  EXPECT_NE(html.find("<code>rpe_trans_percent</code></td><td class=\"v\">n/a"), std::string::npos);
  EXPECT_EQ(html.rfind("</html>\n"), html.size() - 8);
}

}  // namespace
}  // namespace unimap::eval
