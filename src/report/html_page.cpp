#include "report/html_page.hpp"

namespace penumbra {

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

void HtmlPage::heading(const std::string& text, int level) {
  const std::string tag = std::string(1, 'h') + std::to_string(level);
  body_.append("<").append(tag).append(">").append(html_escape(text));
  body_.append("</").append(tag).append(">\n");
}

void HtmlPage::paragraph(const std::string& text) {
  body_ += "<p>" + html_escape(text) + "</p>\n";
}

void HtmlPage::figures(const std::vector<HtmlFigure>& figures) {
  body_ += "<div class=\"grid\">\n";
  for (const HtmlFigure& f : figures) {
    body_ += "<figure>";
    if (f.error.empty()) {
      body_ += "<img src=\"" + html_escape(f.image) + "\" width=\"" + std::to_string(f.width) +
               "\" height=\"" + std::to_string(f.height) + "\" alt=\"" + html_escape(f.caption) +
               "\">";
    } else {
      body_ += "<div class=\"failed\">failed: " + html_escape(f.error) + "</div>";
    }
    body_ += "<figcaption>" + html_escape(f.caption);
    if (!f.command.empty()) body_ += "<code>" + html_escape(f.command) + "</code>";
    body_ += "</figcaption></figure>\n";
  }
  body_ += "</div>\n";
}

void HtmlPage::table(const std::vector<std::vector<std::string>>& rows) {
  body_ += "<table>\n";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    body_ += "<tr>";
    const char* cell = r == 0 ? "th" : "td";
    for (const std::string& text : rows[r]) {
      body_ += std::string("<") + cell + ">" + html_escape(text) + "</" + cell + ">";
    }
    body_ += "</tr>\n";
  }
  body_ += "</table>\n";
}

std::string HtmlPage::finish() const {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
         html_escape(title_) +
         "</title>\n<style>\n"
         "body { font-family: sans-serif; max-width: 1400px; margin: 2em auto; padding: 0 1em; "
         "color: #222; line-height: 1.45; }\n"
         "h1, h2, h3 { font-weight: 600; }\n"
         ".grid { display: flex; flex-wrap: wrap; gap: 12px; }\n"
         "figure { margin: 0; width: min(100%, 440px); }\n"
         "figure img { width: 100%; height: auto; border: 1px solid #ccc; }\n"
         "figcaption { font-size: 0.9em; }\n"
         "figcaption code { display: block; font-size: 0.8em; color: #555; "
         "word-break: break-all; margin-top: 0.3em; }\n"
         ".failed { border: 1px solid #c00; color: #c00; padding: 1em; }\n"
         "table { border-collapse: collapse; margin: 1em 0; }\n"
         "th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: right; }\n"
         "th:first-child, td:first-child { text-align: left; }\n"
         "</style>\n</head>\n<body>\n<h1>" +
         html_escape(title_) + "</h1>\n" + body_ + "</body>\n</html>\n";
}

}  // namespace penumbra
