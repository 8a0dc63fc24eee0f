#include "report/html_page.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace penumbra {

namespace {

std::string percent(int part, int whole) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f%%", whole > 0 ? 100.0 * part / whole : 0.0);
  return text;
}

// The height most of the grid's images have (0 if none): the height its
// rows are shown at.
int row_height(const std::vector<HtmlFigure>& figures) {
  std::map<int, int> count;
  for (const HtmlFigure& f : figures) {
    if (f.error.empty() && f.height > 0 && f.css_class != "crop") ++count[f.height];
  }
  const auto most = std::max_element(count.begin(), count.end(), [](auto& a, auto& b) {
    return a.second < b.second || (a.second == b.second && a.first > b.first);
  });
  return most == count.end() ? 0 : most->first;
}

// `row_height`: the height the grid shows its images at (0: their own).
std::string figure_html(const HtmlFigure& f, int row_height) {
  std::string html = "<figure";
  if (!f.css_class.empty()) html += " class=\"" + html_escape(f.css_class) + "\"";
  for (const auto& [key, value] : f.data) {
    html += " data-" + html_escape(key) + "=\"" + html_escape(value) + "\"";
  }
  html += ">";
  if (f.error.empty()) {
    const std::string link = f.link.empty() ? f.image : f.link;
    html += "<a class=\"frame\" href=\"" + html_escape(link) + "\"><img src=\"" +
            html_escape(f.image) + "\" width=\"" + std::to_string(f.width) + "\" height=\"" +
            std::to_string(f.height) + "\" alt=\"" + html_escape(f.caption) + "\"";
    // Shown at its own size, or scaled down to the row's height; never up.
    int shown_height = f.height;
    if (f.css_class != "crop" && row_height > 0 && f.height > row_height) {
      shown_height = row_height;
    }
    const long shown_width =
        f.height > 0 ? std::lround(double(f.width) * shown_height / f.height) : f.width;
    html += " style=\"width:" + std::to_string(shown_width) +
            "px;height:" + std::to_string(shown_height) + "px\">";
    for (const HtmlOverlay& o : f.overlays) {
      html += "<span class=\"region\" style=\"left:" + percent(o.x, f.width) +
              ";top:" + percent(o.y, f.height) + ";width:" + percent(o.width, f.width) +
              ";height:" + percent(o.height, f.height) + "\">" + html_escape(o.label) + "</span>";
    }
    html += "</a>";
  } else {
    html += "<div class=\"failed\">failed: " + html_escape(f.error) + "</div>";
  }
  html += "<figcaption>" + html_escape(f.caption);
  if (!f.command.empty()) html += "<code>" + html_escape(f.command) + "</code>";
  html += "</figcaption></figure>\n";
  return html;
}

}  // namespace

std::string html_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

HtmlPage::HtmlPage(const std::string& title) : title_(title) {}

void HtmlPage::section(const std::string& id, const std::string& title) {
  if (in_section_) body_ += "</section>\n";
  body_ += "<section id=\"" + html_escape(id) + "\">\n";
  in_section_ = true;
  heading(title);
}

void HtmlPage::heading(const std::string& text, int level) {
  const std::string tag = std::string(1, 'h') + std::to_string(level);
  body_.append("<").append(tag).append(">").append(html_escape(text));
  body_.append("</").append(tag).append(">\n");
}

void HtmlPage::paragraph(const std::string& text) {
  body_ += "<p>" + html_escape(text) + "</p>\n";
}

void HtmlPage::paragraph(const std::string& text, const std::string& link_text,
                         const std::string& href) {
  body_ += "<p>" + html_escape(text) + " <a href=\"" + html_escape(href) + "\">" +
           html_escape(link_text) + "</a>.</p>\n";
}

void HtmlPage::figures(const std::vector<HtmlFigure>& figures, std::size_t group) {
  const int height = row_height(figures);
  body_ += "<div class=\"grid\">\n";
  for (std::size_t i = 0; i < figures.size(); i += group) {
    if (group > 1) body_ += "<div class=\"group\">\n";
    for (std::size_t j = i; j < i + group && j < figures.size(); ++j) {
      body_ += figure_html(figures[j], height);
    }
    if (group > 1) body_ += "</div>\n";
  }
  body_ += "</div>\n";
}

std::string HtmlPage::table_html(const std::vector<std::vector<std::string>>& rows) const {
  // A column is kept when any cell below the header has text (or when
  // there is no row below the header).
  std::size_t columns = 0;
  for (const auto& row : rows) columns = std::max(columns, row.size());
  std::vector<bool> keep(columns, rows.size() < 2);
  for (std::size_t r = 1; r < rows.size(); ++r) {
    for (std::size_t c = 0; c < rows[r].size(); ++c) {
      if (!rows[r][c].empty()) keep[c] = true;
    }
  }
  std::string html = "<table>\n";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    html += "<tr>";
    const char* cell = r == 0 ? "th" : "td";
    for (std::size_t c = 0; c < rows[r].size(); ++c) {
      if (!keep[c]) continue;
      html += std::string("<") + cell + ">" + html_escape(rows[r][c]) + "</" + cell + ">";
    }
    html += "</tr>\n";
  }
  html += "</table>\n";
  return html;
}

void HtmlPage::table(const std::vector<std::vector<std::string>>& rows) {
  body_ += table_html(rows);
}

void HtmlPage::plot(const std::string& svg, const std::vector<std::vector<std::string>>& data) {
  body_ += "<figure class=\"plot\">\n" + svg +
           "<details><summary>The data of this plot</summary>\n" + table_html(data) +
           "</details></figure>\n";
}

void HtmlPage::banner(const std::string& text) {
  banner_ = "<p class=\"banner\">" + html_escape(text) + "</p>\n";
}

void HtmlPage::graphic(const std::string& svg) {
  body_ += svg;
}

void HtmlPage::verdict(const std::string& title, const std::string& intro,
                       const std::vector<VerdictLine>& lines) {
  std::string html = "<section id=\"summary\">\n<h2>" + html_escape(title) + "</h2>\n<p>" +
                     html_escape(intro) + "</p>\n<ul class=\"verdict\">\n";
  for (const VerdictLine& line : lines) {
    html += "<li><b>" + html_escape(line.when) + ":</b> " + html_escape(line.choice) + ". " +
            html_escape(line.before) + "<data value=\"" + html_escape(line.number) + "\">" +
            html_escape(line.number) + "</data>" + html_escape(line.after) + " <a href=\"#" +
            html_escape(line.section) + "\">(" + html_escape(line.section_title) + ")</a></li>\n";
  }
  html += "</ul>\n</section>\n";
  verdict_ = html;
}

std::string HtmlPage::finish() const {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
         html_escape(title_) +
         "</title>\n<style>\n"
         "body { font-family: sans-serif; max-width: 1400px; margin: 2em auto; padding: 0 1em; "
         "color: #222; line-height: 1.45; }\n"
         "h1, h2, h3 { font-weight: 600; }\n"
         ".grid { display: flex; flex-wrap: wrap; gap: 12px; align-items: flex-start; }\n"
         ".group { display: flex; gap: 6px; padding: 4px; background: #f3f3f3; "
         "break-inside: avoid; }\n"
         // A figure is as wide as its image (its inline size), the
         // caption wrapping under it.
         "figure { margin: 0; width: min-content; break-inside: avoid; }\n"
         "figure img { display: block; border: 1px solid #ccc; }\n"
         "figure.crop img { image-rendering: pixelated; }\n"
         "a.frame { display: block; position: relative; line-height: 0; width: fit-content; }\n"
         ".region { position: absolute; border: 2px solid #000; outline: 1px solid #fff; "
         "box-sizing: border-box; color: #000; background: none; font: bold 11px/1 sans-serif; "
         "text-shadow: 0 0 2px #fff, 0 0 2px #fff; padding: 1px; }\n"
         "figcaption { font-size: 0.9em; min-width: 12em; }\n"
         // A font list, not the bare generic "monospace", which browsers
         // shrink to 13 px before the em scaling.
         "figcaption code { display: block; font: 12px/1.35 'DejaVu Sans Mono', Menlo, Consolas, "
         "monospace; color: #333; overflow-wrap: anywhere; margin-top: 0.3em; }\n"
         ".banner { background: #fff4d6; border: 1px solid #e0b040; padding: 0.6em 1em; }\n"
         "svg.colorbar { display: block; width: 480px; max-width: 100%; height: auto; "
         "margin: 0.5em 0; }\n"
         "figure.plot { width: min(100%, 760px); margin: 1em 0; }\n"
         "figure.plot svg { width: 100%; height: auto; }\n"
         "details summary { cursor: pointer; color: #555; font-size: 0.9em; }\n"
         ".verdict li { margin: 0.3em 0; }\n"
         ".failed { border: 1px solid #c00; color: #c00; padding: 1em; }\n"
         "table { border-collapse: collapse; margin: 1em 0; }\n"
         "th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: right; }\n"
         "th:first-child, td:first-child { text-align: left; }\n"
         "</style>\n</head>\n<body>\n<h1>" +
         html_escape(title_) + "</h1>\n" + banner_ + verdict_ + body_ +
         (in_section_ ? "</section>\n" : "") + "</body>\n</html>\n";
}

}  // namespace penumbra
