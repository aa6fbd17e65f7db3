// gpu_lod/wrapper.h: reading the user's file and the drivers' and glslang's logs.
#include "gpu_lod/wrapper.h"

#include <fstream>
#include <regex>
#include <sstream>

namespace fftess::gpulod::detail {

namespace {

struct LogLine {
  int line = 0; // 0: no position
  int column = 0;
  std::string text; // after the position
};

LogLine parseLogLine(const std::string& l) {
  LogLine out;
  out.text = l;
  std::smatch m;
  if (std::regex_search(l, m, std::regex(R"(^(?:ERROR: |WARNING: )?\d+:(\d+)\((\d+)\):?\s*)"))) {
    out.line = std::stoi(m[1]);
    out.column = std::stoi(m[2]);
    out.text = m.suffix();
  } else if (std::regex_search(l, m, std::regex(R"(^\d+\((\d+)\)\s*:?\s*)"))) {
    out.line = std::stoi(m[1]);
    out.text = m.suffix();
  }
  return out;
}

} // namespace

bool readFile(const std::string& path, std::string& out) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return false;
  std::ostringstream ss;
  ss << f.rdbuf();
  out = ss.str();
  return true;
}

bool hasEntryPoint(const std::string& src) { return std::regex_search(src, std::regex(R"(\blodMain\s*\()")); }

bool isWarning(const std::string& text) {
  return text.find("warning") != std::string::npos && text.find("error") == std::string::npos;
}

std::string driverLog(const std::string& log, const std::string& file, bool& wrapper) {
  std::string out;
  std::istringstream in(log);
  std::string l;
  wrapper = false;
  while (std::getline(in, l)) {
    if (l.empty()) continue;
    const LogLine p = parseLogLine(l);
    if (isWarning(p.text)) continue;
    std::string where;
    if (p.line > 0 && p.line < kWrapperLine && !file.empty()) {
      where = file + ":" + std::to_string(p.line) + (p.column > 0 ? ":" + std::to_string(p.column) : "") + ": ";
    } else if (p.line >= kPreludeLine) {
      where = "(fftess prelude, lod/shaders/*.glsl and the interface types) ";
    } else if (p.line >= kWrapperLine) {
      where = "(fftess wrapper) ";
      wrapper = true;
    }
    out += (out.empty() ? "" : "\n") + (p.line > 0 ? where + p.text : l);
  }
  return out.empty() ? log : out;
}

std::string trimLog(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ' || s.back() == '\0')) s.pop_back();
  return s;
}

} // namespace fftess::gpulod::detail
