#pragma once
// A small builder of self-contained HTML: no scripts, no network, styles
// inline, images referenced by relative file names.
#include <string>
#include <utility>
#include <vector>

namespace penumbra {

std::string html_escape(const std::string& text);

// A labelled rectangle drawn over a figure's image, in the image's pixels.
struct HtmlOverlay {
  std::string label;
  int x = 0, y = 0, width = 0, height = 0;
};

struct HtmlFigure {
  std::string image;  // file name relative to the page; empty if the item failed
  int width = 0, height = 0;
  std::string caption;  // plain text
  std::string command;  // the command that re-makes it (plain text)
  std::string error;    // why the item failed, if it did
  // What the image links to: the image itself unless set (a crop links to
  // the full image it was cut from).
  std::string link;
  // "crop": a close-up, always shown at its own size.
  std::string css_class;
  std::vector<std::pair<std::string, std::string>> data;  // data-* attributes
  std::vector<HtmlOverlay> overlays;
};

// One line of the verdict: when, what to use, and the measured number that
// backs it, with a link to the section that shows it.
struct VerdictLine {
  std::string when;     // "Hard contact shadows"
  std::string choice;   // "pcss"
  std::string before;   // text before the number
  std::string number;   // as the linked section prints it
  std::string after;    // text after the number
  std::string section;  // id of the section
  std::string section_title;
};

class HtmlPage {
 public:
  explicit HtmlPage(const std::string& title);

  // Starts a section (closing the one before): <section id="id"><h2>.
  void section(const std::string& id, const std::string& title);
  void heading(const std::string& text, int level = 2);
  void paragraph(const std::string& text);  // plain text, escaped
  // The same, ending in a link: "text <a href="href">link_text</a>."
  void paragraph(const std::string& text, const std::string& link_text, const std::string& href);
  // Figures in a wrapping grid; with group > 1, every `group` figures in a
  // row of their own that the grid never breaks (a map before and after).
  // Images are shown at their own size, never enlarged (a 320x180 frame
  // blown up to a column's width is blurred); an image taller than most
  // of the grid's (a square map among 16:9 frames) is shown at their
  // height, so every row of the grid is as tall as its images.
  void figures(const std::vector<HtmlFigure>& figures, std::size_t group = 1);
  // A table of plain-text cells; the first row is the header. Columns empty
  // in every row below the header are left out.
  void table(const std::vector<std::vector<std::string>>& rows);
  // An inline <svg> plot, with the data it draws in a table under a
  // <details> that opens on a click (and in print).
  void plot(const std::string& svg, const std::vector<std::vector<std::string>>& data);
  // A notice shown above everything else (what kind of run made the page).
  void banner(const std::string& text);
  // An inline <svg> drawn as it is (a colour bar), no data table.
  void graphic(const std::string& svg);
  // The verdict, shown first on the page (after the banner) whenever it is
  // set.
  void verdict(const std::string& title, const std::string& intro,
               const std::vector<VerdictLine>& lines);

  [[nodiscard]] std::string finish() const;

 private:
  std::string table_html(const std::vector<std::vector<std::string>>& rows) const;
  std::string title_;
  std::string banner_;
  std::string verdict_;
  std::string body_;
  bool in_section_ = false;
};

}  // namespace penumbra
