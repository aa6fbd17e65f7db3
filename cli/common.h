// Shared pieces of the fftess command-line tool: exit statuses, error types, atomic report files, number formatting.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace fftess::cli {

// Exit statuses (docs/cli.md). Only cli/ turns findings into these.
enum ExitStatus : int {
  kExitClean = 0,    // nothing wrong found
  kExitFindings = 1, // cracks found (check, sweep)
  kExitUsage = 2,    // bad usage or bad input: one line naming the argument or the file position
  kExitInternal = 3, // internal error (a bug, or the system failed us: disk full, ...)
};

// Bad usage or bad input; what() is the complete one-line reason (argument name or file:line, and the bad token).
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Writes a report to PATH.tmp.XXXXXX next to PATH and renames it over PATH on commit(); a writer destroyed without
// commit() removes its temporary file, so a failed or interrupted run never leaves a partial report behind.
// PATH "-" means stdout (written at commit()).
class AtomicFile {
public:
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  std::string& buffer() { return buffer_; }
  void commit(); // throws std::runtime_error on I/O failure (-> exit 3) and UsageError if the directory is unusable
  const std::string& path() const { return path_; }

private:
  std::string path_;
  std::string buffer_;
  bool committed_ = false;
};

// Writes all of s to stdout at once (one fwrite per call, so a patch block is never half-written by us).
void writeStdout(const std::string& s);

uint32_t floatBits(float f);
std::string hex8(uint32_t v);                 // 8 lowercase hex digits
std::string formatFloat(float f);             // shortest round-trip decimal (%.9g trimmed), nan/inf spelled out
std::string formatNumber(double v);           // for human text: up to 6 significant digits
std::string fixed16(uint32_t v);              // 16.16 value as 0xHHHHHHHH
std::string fractionOf65536(int64_t units2);  // value given in 1/131072 units -> "k/65536" with .5 when needed
std::string quoteToken(const std::string& s); // 'token' with control characters escaped
std::string xmlEscape(const std::string& s);  // & < > " as XML entities (SVG text and attributes)

// Factor tokens, batch lines and the hex output format: tessellator/batch.h (fftess::parseFactor and friends).

} // namespace fftess::cli
