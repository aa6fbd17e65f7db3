// Runs the built fftess binary for end-to-end tests and captures its exit status, stdout and stderr.
#pragma once

#include <string>
#include <vector>

namespace clitest {

struct Result {
  int status = -1; // exit status, or 128 + signal
  std::string out;
  std::string err;
};

// args: arguments after the program name. input: written to the program's stdin.
Result run(const std::vector<std::string>& args, const std::string& input = "");
// Scratch directory for files the tests write (created on first use, unique per process).
std::string tmpDir();
std::string readFile(const std::string& path);
void writeFile(const std::string& path, const std::string& text);
bool fileExists(const std::string& path);
std::vector<std::string> listDir(const std::string& dir);
std::string golden(const std::string& name);  // path inside shared/golden
std::string source(const std::string& name);  // path inside the source tree

// Well-formed XML (one root element, balanced tags, quoted attributes, known entities). On failure returns false
// and sets why to "offset N: reason".
bool wellFormedXml(const std::string& text, std::string& why, std::string* rootName = nullptr);

} // namespace clitest
