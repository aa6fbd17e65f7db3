// Shared pieces of the fftess command-line tool: exit statuses, error types, atomic report files, number formatting.
#pragma once

#include "base/bits.h" // bitsOf, floatOf: the one float <-> bits helper
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace fftess::cli {

// Exit statuses (docs/cli.md). Only cli/ turns findings into these.
enum ExitStatus : int {
  kExitClean = 0,    // nothing wrong found
  kExitFindings = 1, // cracks found (check, sweep)
  kExitUsage = 2,    // bad usage or bad input: one line naming the argument or the file position
  kExitInternal = 3, // internal error (a bug, or the system failed us: disk full, ...)
};

// Bad usage or bad input; what() is the complete one-line reason (argument name or file:line, and the bad token).
// Bad bytes never reach the terminal: the message goes through printable(), cut only past kMaxMessageBytes (room for
// several whole paths of PATH_MAX bytes, escaped: paths are never cut; tokens from files are cut by quoteToken).
constexpr size_t kMaxMessageBytes = 65536;
struct UsageError : std::runtime_error {
  explicit UsageError(const std::string& what);
  // details: lines printed as they are before the "fftess: error: WHAT" line (a compiler's diagnostics, one per
  // line: "file:line:col: error: ..."), "" for none.
  UsageError(const std::string& what, const std::string& details);
  std::string details;
};

// Ctrl-C answered while the work was already done (waiting for a FIFO's reader): exit 130, the reports not written.
struct Interrupted : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// s with control bytes and bytes that are not UTF-8 escaped as \xHH, cut after maxBytes with "... (N bytes)".
std::string printable(const std::string& s, size_t maxBytes = 1000);

// A report file written all or nothing. The constructor checks PATH before any work is done (UsageError naming the
// path: missing directory, a directory, a path under a regular file, ...) and, for a regular file or a new path,
// creates PATH.tmp.XXXXXX in the directory of the file PATH finally names (symlinks are followed: the link stays and
// its target is replaced atomically). write() puts the buffer into that temp file, publish() renames it over the
// target. Anything that is not a regular file (a FIFO, a character device, /dev/stdout, anything under /dev or
// /proc) is never replaced: it is opened and written straight at publish(). A writer destroyed unpublished removes its
// temporary file, so a failed or interrupted run never leaves a partial report behind. PATH "-" means stdout.
class AtomicFile {
public:
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  std::string& buffer() { return buffer_; }
  void write();   // the buffer into the temporary file; std::runtime_error naming the path on I/O failure (-> exit 3)
  void publish(); // rename (or the straight write); std::runtime_error on failure
  void unpublish(); // after publish(): removes a file that did not exist before (all-or-nothing of several reports)
  void commit() { write(), publish(); }
  // Streaming instead of buffer(): s goes out now (stdout, the temporary file, or straight to a FIFO/device);
  // commit() then completes the file. std::runtime_error naming the path on failure.
  void stream(const std::string& s);
  const std::string& path() const { return path_; }
  // Whether stream() writes now without blocking on a reader: a regular file (its temporary file) or stdout; false
  // for a FIFO or a device, which is opened only at publish() (a streaming writer buffers for those instead).
  bool streamsNow() const { return !direct_; }

private:
  std::string path_;   // as given (messages)
  std::string target_; // the file finally written (symlinks followed)
  std::string tmp_;    // temporary file next to target_, "" when written straight or to stdout
  int fd_ = -1, directFd_ = -1, tempSlot_ = -1;
  bool direct_ = false, existed_ = false, written_ = false, published_ = false;
  std::string buffer_;
};

// Temporary report files are also removed when a signal ends the process (SIGINT without InterruptGuard, or the second
// one with it; SIGTERM, SIGHUP): the handler unlinks them and re-raises the signal with its default action.
using SignalHandler = void (*)(int);
SignalHandler removeTempsAndDie();

// A file named on the command line, for refuseSameFiles: the option (or argument name) and the path as given.
struct FileArg {
  std::string option;
  std::string path; // "" = not given (skipped)
};
// Refuses (UsageError naming both options and paths) two outputs that are the same file, or an output that is one of
// the inputs. Compared by the file finally named, not by spelling: symlinks followed, an existing file by st_dev +
// st_ino (hard links, "./x" and "x"), a new one by its resolved directory and name. "-" (stdout) and character devices
// (/dev/null) are never refused. Call before any work and before AtomicFile claims the outputs.
void refuseSameFiles(const std::vector<FileArg>& outputs, const std::vector<FileArg>& inputs = {});

// Writes several reports all or nothing: every temporary file is written first, then all are published; if one
// fails, the ones already published that did not exist before are removed and the error is rethrown.
void commitAll(AtomicFile* const* files, size_t count);

// Writes all of s to stdout at once (one fwrite per call, so a patch block is never half-written by us).
void writeStdout(const std::string& s);
// Flushes stdout; std::runtime_error ("writing to stdout failed: ...", exit 3) if any write to it failed.
void flushStdout();

std::string hex8(uint32_t v);                 // 8 lowercase hex digits
std::string formatFloat(float f);             // shortest round-trip decimal (%.9g trimmed), nan/inf spelled out
std::string formatNumber(double v);           // for human text: up to 6 significant digits
std::string fixed16(uint32_t v);              // 16.16 value as 0xHHHHHHHH
std::string fractionOf65536(int64_t units2);  // value given in 1/131072 units -> "k/65536" with .5 when needed
std::string quoteToken(const std::string& s); // 'token', escaped as printable(), tokens over 80 bytes cut
// 'path', escaped as printable() but never cut: a path the user gave is always shown whole (quoteToken is for tokens
// from file contents).
std::string quotePath(const std::string& s);
std::string xmlEscape(const std::string& s);  // & < > " as XML entities (SVG text and attributes)

// Factor tokens, batch lines and the hex output format: tessellator/batch.h (fftess::parseFactor and friends).

} // namespace fftess::cli
