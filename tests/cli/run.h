// Runs the built fftess binary for end-to-end tests and captures its exit status, stdout and stderr.
#pragma once

#include <functional>
#include <string>
#include <sys/types.h>
#include <vector>

namespace clitest {

struct Result {
  int status = -1; // exit status, or 128 + signal
  std::string out;
  std::string err;
};

// args: arguments after the program name. input: written to the program's stdin.
Result run(const std::vector<std::string>& args, const std::string& input = "");

// For fault injection: stdout to a given path (a device node or FIFO of the test's own), SIGINT once stderr contains
// a text or after a delay, and a hook that runs while the child runs (e.g. reading a FIFO the child writes).
struct RunOptions {
  std::string input;
  bool closeStdin = false;           // start the program with descriptor 0 closed (`<&-`); input is ignored
  std::string stdoutPath;            // "" = captured in Result::out
  std::string sigintWhenErr;         // send SIGINT once stderr contains this ("" = not by text)
  double sigintAfter = -1;           // seconds after the start (or after sigintWhenErr matched); < 0: no SIGINT
  std::function<void(pid_t)> whileRunning; // called once right after the start, before waiting
  int signal = 2;                    // the signal sigintAfter sends (SIGINT; any other to test fatal signals)
  double watchdog = 10;              // seconds after the signal: SIGKILL if still running (TimedResult::watchdogFired)
};
struct TimedResult : Result {
  bool interrupted = false;          // the signal was sent
  double exitAfterSigint = -1;       // seconds from the signal to exit
  bool watchdogFired = false;        // still running `watchdog` seconds after the signal: killed
  long maxRssKb = -1;                // the child's peak resident set size (wait4's ru_maxrss)
};
TimedResult runWith(const std::vector<std::string>& args, const RunOptions& options);
// The binary under test (FFTESS_TEST_BINARY in the environment overrides the built one).
const char* binary();
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
