// The report's HTML: columns empty below the header are left out, grouped
// figures stay in one row, images link to their full size, the verdict
// comes first.
#include "report/html_page.hpp"

#include <gtest/gtest.h>

namespace {

TEST(HtmlPage, LeavesOutColumnsEmptyInEveryRow) {
  penumbra::HtmlPage page("t");
  page.table({{"technique", "SAT rows", "total"}, {"hard", "", "1.0"}, {"msm", "", "2.0"}});
  const std::string html = page.finish();
  EXPECT_EQ(html.find("SAT rows"), std::string::npos);
  EXPECT_NE(html.find("<th>total</th>"), std::string::npos);
  EXPECT_NE(html.find("<tr><td>msm</td><td>2.0</td></tr>"), std::string::npos);
}

TEST(HtmlPage, GroupsFiguresAndLinksImages) {
  penumbra::HtmlPage page("t");
  std::vector<penumbra::HtmlFigure> figures(4);
  const char* names[] = {"f0.png", "f1.png", "f2.png", "f3.png"};
  for (int i = 0; i < 4; ++i) {
    figures[i].image = names[i];
    figures[i].width = figures[i].height = 8;
  }
  figures[3].link = "full.png";
  page.figures(figures, 2);
  const std::string html = page.finish();
  EXPECT_NE(html.find("<div class=\"group\">\n<figure><a class=\"frame\" href=\"f0.png\"><img "
                      "src=\"f0.png\""),
            std::string::npos);
  EXPECT_NE(html.find("</figure>\n<figure><a class=\"frame\" href=\"f1.png\">"), std::string::npos)
      << "f0 and f1 in one group";
  EXPECT_NE(html.find("href=\"full.png\"><img src=\"f3.png\""), std::string::npos);
}

// Images are shown at their own size, never enlarged; a square map among
// 16:9 frames is shown at their height, so the row stays aligned.
TEST(HtmlPage, ShowsImagesAtTheirOwnSizeAndRowsAtOneHeight) {
  penumbra::HtmlPage page("t");
  std::vector<penumbra::HtmlFigure> figures(4);
  const char* names[] = {"f0.png", "f1.png", "f2.png", "f3.png"};
  for (int i = 0; i < 4; ++i) {
    figures[i].image = names[i];
    figures[i].width = 320;
    figures[i].height = 180;
  }
  figures[2].width = figures[2].height = 512;  // a shadow map
  figures[3].width = 160;                      // a crop, at its size
  figures[3].height = 88;
  figures[3].css_class = "crop";
  page.figures(figures);
  const std::string html = page.finish();
  EXPECT_NE(html.find("<img src=\"f0.png\" width=\"320\" height=\"180\" alt=\"\" "
                      "style=\"width:320px;height:180px\">"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<img src=\"f2.png\" width=\"512\" height=\"512\" alt=\"\" "
                      "style=\"width:180px;height:180px\">"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("style=\"width:160px;height:88px\""), std::string::npos);
  // No rule stretches an image to its column.
  EXPECT_EQ(html.find("img { width: 100%"), std::string::npos);
}

TEST(HtmlPage, TheBannerComesBeforeTheVerdict) {
  penumbra::HtmlPage page("t");
  page.section("errors", "6. Errors");
  page.verdict("Summary", "intro", {});
  page.banner("quick & small");
  const std::string html = page.finish();
  const auto banner = html.find("<p class=\"banner\">quick &amp; small</p>");
  ASSERT_NE(banner, std::string::npos);
  EXPECT_LT(html.find("</h1>"), banner);
  EXPECT_LT(banner, html.find("<section id=\"summary\">"));
}

TEST(HtmlPage, TheVerdictComesFirstAndSectionsClose) {
  penumbra::HtmlPage page("t");
  page.section("errors", "6. Errors");
  page.paragraph("a & b");
  page.section("timings", "8. Times");
  page.verdict("Summary", "intro",
               {{"Hard contact", "pcss", "error ", "0.0090", ".", "errors", "section 6"}});
  const std::string html = page.finish();
  const auto summary = html.find("<section id=\"summary\">");
  ASSERT_NE(summary, std::string::npos);
  EXPECT_LT(summary, html.find("<section id=\"errors\">"));
  EXPECT_NE(html.find("<data value=\"0.0090\">0.0090</data>"), std::string::npos);
  EXPECT_NE(html.find("<a href=\"#errors\">"), std::string::npos);
  EXPECT_NE(html.find("a &amp; b"), std::string::npos);
  EXPECT_NE(html.find("</section>\n<section id=\"timings\">"), std::string::npos);
  EXPECT_NE(html.find("</section>\n</body>"), std::string::npos);
}

}  // namespace
