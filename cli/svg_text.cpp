// Text in the SVG pictures (svg_text.h).
#include "svg_text.h"
#include "common.h"

#include <cstdio>
#include <cstring>

namespace fftess::cli {

namespace {

// The glyph class bound (svg_text.h) of an ASCII character, in em; any other code point counts as wide.
double sansEm(unsigned char c) {
  if (c >= 0x80) return 1.0;
  if (std::strchr(" .,:;'|!()[]/ijlftr-", c)) return 0.42;
  if (std::strchr("mwMW@%=+<>~#&", c)) return 1.0;
  if (c >= 'A' && c <= 'Z') return 0.8;
  return 0.66;
}

// The byte length of the UTF-8 sequence starting with lead byte c (1 for stray continuation bytes).
size_t glyphBytes(unsigned char c) { return c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 1; }

} // namespace

std::string svgHead(double width, double height, const std::string& title) {
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" "
                "height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\">\n",
                width, height, width, height);
  return buf + ("<title>" + xmlEscape(title) + "</title>\n");
}

double svgTextWidth(const std::string& text, double px, bool monospace) {
  double em = 0;
  for (size_t i = 0; i < text.size(); i += glyphBytes(static_cast<unsigned char>(text[i])))
    em += monospace ? 0.62 : sansEm(static_cast<unsigned char>(text[i]));
  return em * px;
}

std::vector<std::string> svgWrap(const std::string& text, double px, bool monospace, double maxWidth) {
  std::vector<std::string> lines;
  std::string line;
  size_t i = 0;
  while (i < text.size()) {
    size_t end = text.find(' ', i);
    if (end == std::string::npos) end = text.size();
    std::string word = text.substr(i, end - i);
    i = end + 1;
    const std::string joined = line.empty() ? word : line + " " + word;
    if (svgTextWidth(joined, px, monospace) <= maxWidth) {
      line = joined;
      continue;
    }
    if (!line.empty()) lines.push_back(line);
    line.clear();
    // A word wider than a line: cut it at code point boundaries.
    while (svgTextWidth(word, px, monospace) > maxWidth) {
      size_t cut = 0, next = 0;
      while (next < word.size() && svgTextWidth(word.substr(0, next + glyphBytes(static_cast<unsigned char>(word[next]))), px, monospace) <= maxWidth)
        cut = next += glyphBytes(static_cast<unsigned char>(word[next]));
      if (cut == 0) cut = glyphBytes(static_cast<unsigned char>(word[0])); // not even one glyph fits: one per line
      lines.push_back(word.substr(0, cut));
      word = word.substr(cut);
    }
    line = word;
  }
  if (!line.empty() || lines.empty()) lines.push_back(line);
  return lines;
}

double svgTextLines(std::string& out, const char* cls, const std::string& text, double px, bool monospace, double x,
                    double y, double maxWidth, double lineHeight) {
  char buf[96];
  for (const std::string& line : svgWrap(text, px, monospace, maxWidth)) {
    std::snprintf(buf, sizeof buf, "<text class=\"%s\" x=\"%.1f\" y=\"%.1f\">", cls, x, y);
    out += buf + xmlEscape(line) + "</text>\n";
    y += lineHeight;
  }
  return y;
}

} // namespace fftess::cli
