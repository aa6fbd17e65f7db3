// A replay driver for libFuzzer targets that builds with g++ (no clang, no libFuzzer): runs every file of the given
// corpus directories through LLVMFuzzerTestOneInput, then `-runs=N` deterministic mutations of them (byte flips,
// inserts, deletions, duplicated ranges, dictionary tokens; splitmix64 from `-seed=S`). Under the sanitizer build
// this is a short fuzz run with ASan+UBSan in CI. A crash or sanitizer report ends the process (the test fails); the
// input that did it is written to ./fuzz-crash-input first.
//   fuzz_scene_replay [-runs=N] [-seed=S] DIR...
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

struct Rng {
  uint64_t s;
  uint64_t next() {
    uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  size_t below(size_t n) { return n == 0 ? 0 : static_cast<size_t>(next() % n); }
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

void runOne(const std::string& input) {
  {
    std::ofstream f("fuzz-crash-input", std::ios::binary | std::ios::trunc);
    f << input;
  }
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
  for (const std::string& c : corpus) runOne(c);
  Rng rng{seed};
  for (long i = 0; i < runs; ++i) runOne(mutate(corpus[rng.below(corpus.size())], rng));
  std::remove("fuzz-crash-input");
  std::printf("fuzz replay: %zu corpus inputs and %ld mutations, no crash\n", corpus.size(), runs);
  return 0;
}
