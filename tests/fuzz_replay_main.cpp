// A replay driver for libFuzzer targets that builds with g++ (no clang, no libFuzzer): runs every file of the given
// corpus directories through LLVMFuzzerTestOneInput, then `-runs=N` deterministic mutations of them (byte flips,
// inserts, deletions, duplicated ranges, dictionary tokens; splitmix64 from `-seed=S`). Under the sanitizer build
// this is a short fuzz run with ASan+UBSan in CI. A crash or sanitizer report ends the process (the test fails); the
// input that did it is written to ./fuzz-crash-input on the way out (a sanitizer's death callback, or a handler for
// the fatal signals). Nothing is written while inputs pass: rewriting the file before every input made the replay
// wait on the disk (6 s per 2,000 inputs on ext4).
//   test_verify_fuzz_replay [-runs=N] [-seed=S] DIR...
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <csignal>
#include <dirent.h>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

#include "base/splitmix64.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);
// The sanitizers' runtime calls this before it ends the process on a report; weak: absent without sanitizers.
extern "C" void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

namespace {

// splitmix64 (base/splitmix64.h); below(0) is 0 here (an empty input has no position to pick).
struct Rng {
  fftess::SplitMix64 g;
  uint64_t next() { return g.next(); }
  size_t below(size_t n) { return n == 0 ? 0 : static_cast<size_t>(g.next() % n); }
};

const char* const kDictionary[] = {"=",     "[",      "]",      "\"",     "\0",   "\n",    "nan",   "inf",   "-inf",
                                   "1e-45", "1e38",   "-1",     "0",      "1e309", "[[",    "]]",    ".",     "'",
                                   "0x7fffffff", "9223372036854775807", "\xff", "\"\"\"", "#", ","};

std::string mutate(std::string s, Rng& rng) {
  const int n = 1 + static_cast<int>(rng.below(4));
  for (int k = 0; k < n; ++k) {
    const size_t at = rng.below(s.size() + 1);
    switch (rng.below(5)) {
    case 0:
      if (!s.empty()) s[rng.below(s.size())] ^= static_cast<char>(1u << rng.below(8));
      break;
    case 1: s.insert(at, 1, static_cast<char>(rng.below(256))); break;
    case 2:
      if (at < s.size()) s.erase(at, 1 + rng.below(std::min<size_t>(16, s.size() - at)));
      break;
    case 3:
      if (at < s.size()) {
        const std::string piece = s.substr(at, 1 + rng.below(32));
        s.insert(rng.below(s.size() + 1), piece);
      }
      break;
    default: {
      const char* t = kDictionary[rng.below(sizeof kDictionary / sizeof *kDictionary)];
      s.insert(at, std::string(t, *t ? std::strlen(t) : 1));
    }
    }
  }
  return s;
}

// The input being run, for the crash writers (async-signal-safe: open/write/close only).
const std::string* gCurrent = nullptr;

void writeCrashInput() {
  const std::string* in = gCurrent;
  if (!in) return;
  const int fd = ::open("fuzz-crash-input", O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) return;
  size_t done = 0;
  while (done < in->size()) {
    const ssize_t n = ::write(fd, in->data() + done, in->size() - done);
    if (n <= 0) break;
    done += static_cast<size_t>(n);
  }
  ::close(fd);
}

extern "C" void onFatalSignal(int sig) {
  writeCrashInput();
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

void installCrashWriters() {
  if (__sanitizer_set_death_callback) __sanitizer_set_death_callback(writeCrashInput);
  for (int sig : {SIGSEGV, SIGABRT, SIGFPE, SIGBUS, SIGILL}) std::signal(sig, onFatalSignal);
}

void runOne(const std::string& input) {
  gCurrent = &input;
  LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(input.data()), input.size());
}

} // namespace

int main(int argc, char** argv) {
  long runs = 0;
  uint64_t seed = 1;
  std::vector<std::string> corpus;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("-runs=", 0) == 0) runs = std::strtol(a.c_str() + 6, nullptr, 10);
    else if (a.rfind("-seed=", 0) == 0) seed = std::strtoull(a.c_str() + 6, nullptr, 10);
    else if (DIR* d = ::opendir(a.c_str())) {
      std::vector<std::string> names;
      while (dirent* e = ::readdir(d))
        if (e->d_name[0] != '.') names.push_back(a + "/" + e->d_name);
      ::closedir(d);
      std::sort(names.begin(), names.end());
      for (const std::string& p : names) {
        std::ifstream f(p, std::ios::binary);
        std::ostringstream ss;
        ss << f.rdbuf();
        corpus.push_back(ss.str());
      }
    } else {
      std::fprintf(stderr, "fuzz replay: cannot read corpus directory %s\n", a.c_str());
      return 2;
    }
  }
  if (corpus.empty()) corpus.push_back("");
  std::remove("fuzz-crash-input");
  installCrashWriters();
  for (const std::string& c : corpus) runOne(c);
  Rng rng{seed};
  for (long i = 0; i < runs; ++i) runOne(mutate(corpus[rng.below(corpus.size())], rng));
  gCurrent = nullptr;
  std::printf("fuzz replay: %zu corpus inputs and %ld mutations, no crash\n", corpus.size(), runs);
  return 0;
}
