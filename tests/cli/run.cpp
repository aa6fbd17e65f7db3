#include "run.h"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <fstream>
#include <spawn.h>
#include <sstream>
#include <stdexcept>
#include <sys/stat.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace clitest {

// ---- the JSON reports of every run, collected for tests/schema ----------------------------------------------------
// Each run that exits 0 or 1 and was asked for a JSON report (the file after --json of check, sweep, merge, prove and
// bench; stdout for --json - and for the --json flag of compare, driver-check and explain) leaves a copy of the report
// in FFTESS_TEST_REPORTS as PID.N.json (its command line in PID.N.cmd); "schema:every JSON report of the cli tests
// validates" checks them against docs/schema. A file is copied only when this run wrote it (new, or another inode,
// mtime or size than before the run), so inputs a test corrupts on purpose do not count.
namespace {

struct JsonTargets {
  std::vector<std::string> files;
  bool toStdout = false;
};

JsonTargets jsonTargets(const std::vector<std::string>& args) {
  JsonTargets t;
  std::string command;
  for (const std::string& a : args)
    if (!a.empty() && a[0] != '-') {
      command = a;
      break;
    }
  const bool flag = command == "compare" || command == "driver-check" || command == "explain";
  for (size_t i = 0; i < args.size(); ++i) {
    std::string value;
    if (args[i] == "--json" && flag) value = "-";
    else if (args[i] == "--json" && i + 1 < args.size()) value = args[i + 1];
    else if (args[i].rfind("--json=", 0) == 0) value = args[i].substr(7);
    else continue;
    if (value == "-") t.toStdout = true;
    else t.files.push_back(value);
  }
  return t;
}

bool sameFile(const struct stat& a, const struct stat& b) {
  return a.st_ino == b.st_ino && a.st_dev == b.st_dev && a.st_size == b.st_size &&
         a.st_mtim.tv_sec == b.st_mtim.tv_sec && a.st_mtim.tv_nsec == b.st_mtim.tv_nsec;
}

void collectReport(const std::string& text, const std::vector<std::string>& args) {
#ifdef FFTESS_TEST_REPORTS
  static int counter = 0;
  const std::string dir = FFTESS_TEST_REPORTS;
  ::mkdir(dir.c_str(), 0755);
  const std::string base = dir + "/" + std::to_string(::getpid()) + "." + std::to_string(counter++);
  std::string cmd = "fftess";
  for (const std::string& a : args) cmd += " " + a;
  writeFile(base + ".json", text);
  writeFile(base + ".cmd", cmd + "\n");
#else
  (void)text, (void)args;
#endif
}

// One line per run in PID.runs: "json" (asked for a JSON report, exited 0 or 1, the report collected), "unread" (asked
// for one, exited 0 or 1, but it went to a FIFO, a device or a stdout of the test's own: not collected) or "other", so
// the schema test knows a run that collected nothing from a collection that is broken.
void logRun(const char* what) {
#ifdef FFTESS_TEST_REPORTS
  const std::string dir = FFTESS_TEST_REPORTS;
  ::mkdir(dir.c_str(), 0755);
  std::ofstream(dir + "/" + std::to_string(::getpid()) + ".runs", std::ios::app) << what << "\n";
#else
  (void)what;
#endif
}

} // namespace

std::string tmpDir() {
  static std::string dir = [] {
    std::string base = FFTESS_TEST_TMP;
    ::mkdir(base.c_str(), 0755);
    std::string d = base + "/run." + std::to_string(::getpid());
    ::mkdir(d.c_str(), 0755);
    return d;
  }();
  return dir;
}

std::string readFile(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("cannot read " + path);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

void writeFile(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
  if (!f) throw std::runtime_error("cannot write " + path);
}

bool fileExists(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0;
}

std::vector<std::string> listDir(const std::string& dir) {
  std::vector<std::string> out;
  if (DIR* d = ::opendir(dir.c_str())) {
    while (dirent* e = ::readdir(d))
      if (std::strcmp(e->d_name, ".") != 0 && std::strcmp(e->d_name, "..") != 0) out.push_back(e->d_name);
    ::closedir(d);
  }
  return out;
}

std::string golden(const std::string& name) { return std::string(FFTESS_GOLDEN_DIR) + "/" + name; }
std::string source(const std::string& name) { return std::string(FFTESS_SOURCE_ROOT) + "/" + name; }

const char* binary() {
  const char* b = std::getenv("FFTESS_TEST_BINARY");
  return b && *b ? b : FFTESS_BINARY;
}

Result run(const std::vector<std::string>& args, const std::string& input) {
  RunOptions o;
  o.input = input;
  return runWith(args, o);
}

TimedResult runWith(const std::vector<std::string>& args, const RunOptions& o) {
  static int counter = 0;
  const std::string base = tmpDir() + "/io" + std::to_string(counter++);
  const std::string in = base + ".in", out = base + ".out", err = base + ".err";
  writeFile(in, o.input);
  writeFile(err, "");
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  if (o.closeStdin) posix_spawn_file_actions_addclose(&fa, 0);
  else posix_spawn_file_actions_addopen(&fa, 0, in.c_str(), O_RDONLY, 0);
  if (o.stdoutPath.empty())
    posix_spawn_file_actions_addopen(&fa, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  else
    posix_spawn_file_actions_addopen(&fa, 1, o.stdoutPath.c_str(), O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const JsonTargets targets = jsonTargets(args);
  std::vector<std::pair<bool, struct stat>> before; // per target file: existed, its stat
  for (const std::string& f : targets.files) {
    struct stat st {};
    const bool existed = ::stat(f.c_str(), &st) == 0;
    before.emplace_back(existed, st);
  }
  std::vector<std::string> all{binary()};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  TimedResult r;
  // The child starts with every signal at its default action and none blocked, whatever this process inherited.
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t every, none;
  sigfillset(&every);
  sigemptyset(&none);
  posix_spawnattr_setsigdefault(&attr, &every);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  const int spawned = posix_spawn(&pid, binary(), &fa, &attr, argv.data(), environ);
  posix_spawnattr_destroy(&attr);
  posix_spawn_file_actions_destroy(&fa);
  if (spawned != 0) throw std::runtime_error(std::string("cannot start ") + binary());
  if (o.whileRunning) o.whileRunning(pid);
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  int st = 0;
  struct rusage usage {};
  if (o.sigintAfter >= 0) {
    bool matched = o.sigintWhenErr.empty();
    auto from = start;
    Clock::time_point sent;
    for (;;) {
      if (::wait4(pid, &st, WNOHANG, &usage) == pid) break;
      if (!matched && readFile(err).find(o.sigintWhenErr) != std::string::npos) matched = true, from = Clock::now();
      if (matched && !r.interrupted && since(from) >= o.sigintAfter) {
        ::kill(pid, o.signal);
        r.interrupted = true;
        sent = Clock::now();
      }
      if (r.interrupted && !r.watchdogFired && since(sent) >= o.watchdog) {
        ::kill(pid, SIGKILL);
        r.watchdogFired = true;
      }
      ::usleep(2000);
    }
    if (r.interrupted) r.exitAfterSigint = since(sent);
  } else {
    ::wait4(pid, &st, 0, &usage);
  }
  r.maxRssKb = usage.ru_maxrss;
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
  if (o.stdoutPath.empty()) r.out = readFile(out);
  r.err = readFile(err);
  const bool wantsJson = (r.status == 0 || r.status == 1) && (targets.toStdout || !targets.files.empty());
  int collected = 0;
  if (wantsJson) {
    if (targets.toStdout && o.stdoutPath.empty() && !r.out.empty()) collectReport(r.out, args), ++collected;
    for (size_t i = 0; i < targets.files.size(); ++i) {
      struct stat st {};
      if (::stat(targets.files[i].c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
      if (before[i].first && sameFile(before[i].second, st)) continue; // not written by this run
      collectReport(readFile(targets.files[i]), args), ++collected;
    }
  }
  logRun(!wantsJson ? "other" : collected ? "json" : "unread");
  ::unlink(in.c_str());
  ::unlink(out.c_str());
  ::unlink(err.c_str());
  // In the sanitizer build a report ends the binary with exit status 1, which is also fftess's "findings" status:
  // a test expecting 1 would pass. The report's own words fail the test instead, whatever the status.
  for (const char* report : {"ERROR: AddressSanitizer", "ERROR: LeakSanitizer", "SUMMARY: UndefinedBehaviorSanitizer"})
    if (r.err.find(report) != std::string::npos)
      throw std::runtime_error("the fftess binary under test reported a sanitizer error:\n" + r.err);
  return r;
}

} // namespace clitest
