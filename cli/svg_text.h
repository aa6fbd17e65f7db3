// Text in the SVG pictures (check --svg, check --view, sweep --svg): widths estimated conservatively, so that a legend
// is wrapped to fit its picture instead of running past the right edge.
#pragma once

#include <string>
#include <vector>

namespace fftess::cli {

// The document's opening: the XML prolog, <svg> of width x height with the same viewBox, and its <title> (the command
// line, with the user's path whole: never through a fixed buffer).
std::string svgHead(double width, double height, const std::string& title);

// An upper bound of the width in pixels of `text` (UTF-8, one glyph per code point) at font size `px`. Monospace:
// 0.62 em per glyph (the common monospace fonts are 0.6 em). Sans-serif, per glyph class, bounds of the advance
// widths of DejaVu Sans (the widest common sans; Liberation Sans and Arial are narrower): narrow glyphs
// (space . , : ; ' | ! ( ) [ ] / i j l f t r -) 0.42 em, wide ones (m w M W @ % = + < > ~ # &) 1.0 em, other capitals
// 0.8 em, everything else 0.66 em.
double svgTextWidth(const std::string& text, double px, bool monospace);

// `text` split at spaces into lines no wider than maxWidth (svgTextWidth); a word wider than a line on its own is cut.
std::vector<std::string> svgWrap(const std::string& text, double px, bool monospace, double maxWidth);

// Writes `text` wrapped to maxWidth as <text class="cls"> lines at x, the first baseline at y, lineHeight apart
// (XML-escaped); returns the baseline after the last line.
double svgTextLines(std::string& out, const char* cls, const std::string& text, double px, bool monospace, double x,
                    double y, double maxWidth, double lineHeight);

} // namespace fftess::cli
