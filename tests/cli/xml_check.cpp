// A small XML well-formedness checker (enough for SVG: prolog, comments, elements, attributes, text, entities).
// It checks what a conforming parser would reject: unbalanced or crossed tags, unquoted or duplicate attributes,
// stray '<' or '&', unknown entities, text or a second element outside the root.
#include "run.h"

#include <cctype>
#include <set>
#include <vector>

namespace clitest {
namespace {

struct P {
  const std::string& s;
  size_t i = 0;
  std::string why;
  bool fail(const std::string& w) {
    why = "offset " + std::to_string(i) + ": " + w;
    return false;
  }
  bool at(const char* lit) const { return s.compare(i, std::char_traits<char>::length(lit), lit) == 0; }
  void ws() {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
  }
  static bool nameStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == ':'; }
  static bool nameChar(char c) {
    return nameStart(c) || std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '.';
  }
  bool name(std::string& out) {
    if (i >= s.size() || !nameStart(s[i])) return fail("expected a name");
    size_t b = i;
    while (i < s.size() && nameChar(s[i])) ++i;
    out = s.substr(b, i - b);
    return true;
  }
  bool entity() { // at '&'
    size_t semi = s.find(';', i);
    if (semi == std::string::npos || semi - i > 10) return fail("bare '&'");
    std::string e = s.substr(i + 1, semi - i - 1);
    static const std::set<std::string> known{"amp", "lt", "gt", "quot", "apos"};
    bool ok = known.count(e) > 0;
    if (!ok && e.size() > 1 && e[0] == '#') {
      ok = true;
      size_t k = 1;
      bool hex = e[1] == 'x';
      if (hex) k = 2;
      if (k >= e.size()) ok = false;
      for (; k < e.size(); ++k)
        ok = ok && (hex ? std::isxdigit(static_cast<unsigned char>(e[k])) : std::isdigit(static_cast<unsigned char>(e[k])));
    }
    if (!ok) return fail("unknown entity &" + e + ";");
    i = semi + 1;
    return true;
  }
  bool misc() { // comments, processing instructions, whitespace
    for (;;) {
      ws();
      if (at("<!--")) {
        size_t e = s.find("-->", i + 4);
        if (e == std::string::npos) return fail("unterminated comment");
        i = e + 3;
      } else if (at("<?")) {
        size_t e = s.find("?>", i + 2);
        if (e == std::string::npos) return fail("unterminated processing instruction");
        i = e + 2;
      } else {
        return true;
      }
    }
  }
  bool element(std::string* rootName) {
    std::vector<std::string> stack;
    do {
      if (at("<!--")) {
        size_t e = s.find("-->", i + 4);
        if (e == std::string::npos) return fail("unterminated comment");
        i = e + 3;
      } else if (at("<![CDATA[")) {
        size_t e = s.find("]]>", i);
        if (e == std::string::npos) return fail("unterminated CDATA");
        i = e + 3;
      } else if (at("</")) {
        i += 2;
        std::string n;
        if (!name(n)) return false;
        ws();
        if (i >= s.size() || s[i] != '>') return fail("expected '>' in end tag");
        ++i;
        if (stack.empty() || stack.back() != n) return fail("end tag </" + n + "> does not match");
        stack.pop_back();
      } else if (at("<")) {
        ++i;
        std::string n;
        if (!name(n)) return false;
        if (stack.empty() && rootName) *rootName = n;
        std::set<std::string> attrs;
        for (;;) {
          size_t before = i;
          ws();
          if (at("/>")) {
            i += 2;
            break;
          }
          if (at(">")) {
            ++i;
            stack.push_back(n);
            break;
          }
          if (i == before) return fail("expected whitespace before attribute");
          std::string a;
          if (!name(a)) return false;
          if (!attrs.insert(a).second) return fail("duplicate attribute " + a);
          ws();
          if (i >= s.size() || s[i] != '=') return fail("expected '=' after attribute " + a);
          ++i;
          ws();
          if (i >= s.size() || (s[i] != '"' && s[i] != '\'')) return fail("unquoted attribute " + a);
          char q = s[i++];
          while (i < s.size() && s[i] != q) {
            if (s[i] == '<') return fail("'<' in attribute value");
            if (s[i] == '&') {
              if (!entity()) return false;
            } else {
              ++i;
            }
          }
          if (i >= s.size()) return fail("unterminated attribute value");
          ++i;
        }
      } else if (i < s.size() && s[i] == '&') {
        if (!entity()) return false;
      } else if (i < s.size()) {
        ++i; // character data
      } else {
        return fail("document ends inside <" + stack.back() + ">");
      }
    } while (!stack.empty());
    return true;
  }
};

} // namespace

bool wellFormedXml(const std::string& text, std::string& why, std::string* rootName) {
  P p{text, 0, {}};
  if (!p.misc()) return why = p.why, false;
  if (!p.at("<")) {
    p.fail("no root element");
    why = p.why;
    return false;
  }
  if (!p.element(rootName)) return why = p.why, false;
  if (!p.misc()) return why = p.why, false;
  if (p.i != text.size()) {
    p.fail("content after the root element");
    why = p.why;
    return false;
  }
  return true;
}

} // namespace clitest
