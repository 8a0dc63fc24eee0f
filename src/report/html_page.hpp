#pragma once
// A small builder of self-contained HTML: no scripts, no network, styles
// inline, images referenced by relative file names.
#include <string>
#include <vector>

namespace penumbra {

std::string html_escape(const std::string& text);

struct HtmlFigure {
  std::string image;  // file name relative to the page; empty if the item failed
  int width = 0, height = 0;
  std::string caption;  // plain text
  std::string command;  // the command that re-makes it (plain text)
  std::string error;    // why the item failed, if it did
};

class HtmlPage {
 public:
  explicit HtmlPage(const std::string& title);

  void heading(const std::string& text, int level = 2);
  void paragraph(const std::string& text);  // plain text, escaped
  void figures(const std::vector<HtmlFigure>& figures);
  // A table of plain-text cells; the first row is the header.
  void table(const std::vector<std::vector<std::string>>& rows);

  [[nodiscard]] std::string finish() const;

 private:
  std::string title_;
  std::string body_;
};

}  // namespace penumbra
