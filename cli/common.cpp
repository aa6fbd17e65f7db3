#include "common.h"
#include "progress.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

#include <vector>

namespace fftess::cli {

namespace {

std::string dirOf(const std::string& p) {
  const size_t slash = p.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : p.substr(0, slash);
}

bool under(const std::string& p, const char* dir) { return p.compare(0, std::strlen(dir), dir) == 0; }

// Temporary files alive now, for the signal handler (async-signal-safe: fixed buffers, atomics, unlink).
constexpr int kMaxTemps = 16;
char gTemps[kMaxTemps][4096];
std::atomic<bool> gTempUsed[kMaxTemps];

extern "C" void onFatalSignal(int sig) {
  for (int i = 0; i < kMaxTemps; ++i)
    if (gTempUsed[i].load()) ::unlink(gTemps[i]);
  std::signal(sig, SIG_DFL);
  std::raise(sig); // delivered when the handler returns (the signal is blocked in it): the default action
}

// Every signal whose default action ends the process (SIGKILL and SIGSTOP cannot be caught).
void installCleanup() {
  static bool done = false;
  if (done) return;
  done = true;
  const int fatal[] = {SIGHUP,  SIGINT,  SIGQUIT, SIGILL,  SIGTRAP,   SIGABRT, SIGBUS,  SIGFPE,  SIGUSR1,
                       SIGSEGV, SIGUSR2, SIGPIPE, SIGALRM, SIGTERM,   SIGSTKFLT, SIGXCPU, SIGXFSZ, SIGVTALRM,
                       SIGPROF, SIGIO,   SIGPWR,  SIGSYS};
  auto install = [](int sig) { // only where nobody else handles the signal (an ignored one stays ignored)
    struct sigaction old;
    if (::sigaction(sig, nullptr, &old) != 0 || (old.sa_flags & SA_SIGINFO) || old.sa_handler != SIG_DFL) return;
    struct sigaction sa {};
    sa.sa_handler = onFatalSignal;
    sigfillset(&sa.sa_mask); // one handler at a time: a second signal waits, then finds the files gone
    sa.sa_flags = SA_RESTART;
    ::sigaction(sig, &sa, nullptr);
  };
  for (int sig : fatal) install(sig);
  for (int sig = SIGRTMIN; sig <= SIGRTMAX; ++sig) install(sig);
}

int registerTemp(const std::string& path) { // from the main thread only
  if (path.size() >= sizeof gTemps[0]) return -1;
  for (int i = 0; i < kMaxTemps; ++i) {
    if (gTempUsed[i].load()) continue;
    std::memcpy(gTemps[i], path.c_str(), path.size() + 1);
    gTempUsed[i].store(true);
    installCleanup();
    return i;
  }
  return -1;
}

void unregisterTemp(int slot) {
  if (slot >= 0) gTempUsed[slot].store(false);
}

[[noreturn]] void cannotWrite(const std::string& path, const std::string& why) {
  throw UsageError("cannot write " + quotePath(path) + ": " + why);
}

} // namespace

// The file a path finally names: symlinks followed one by one (a dangling link names the file to create), magic
// links under /proc and /dev left as they are. False with why set on a loop or an unreadable link.
static bool followLinks(const std::string& path, std::string& target, std::string& why) {
  target = path;
  for (int hops = 0;; ++hops) {
    struct stat st;
    if (::lstat(target.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return true;
    if (hops >= 40) return why = "too many levels of symbolic links", false;
    std::string link(4096, '\0');
    const ssize_t n = ::readlink(target.c_str(), link.data(), link.size());
    if (n < 0 || static_cast<size_t>(n) >= link.size()) return why = std::strerror(errno), false;
    link.resize(static_cast<size_t>(n));
    if (under(target, "/proc/") || under(target, "/dev/")) return true; // magic links (/dev/stdout): as they are
    target = link.front() == '/' ? link : dirOf(target) + "/" + link;
  }
}

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  if (path_ == "-") return;
  if (path_.empty()) cannotWrite(path_, "empty path");
  // Follow symlinks ourselves (a dangling link names the file to create); never rename over the link.
  std::string why;
  if (!followLinks(path_, target_, why)) cannotWrite(path_, why);
  struct stat st;
  if (::stat(target_.c_str(), &st) == 0) {
    existed_ = true;
    if (S_ISDIR(st.st_mode)) cannotWrite(path_, "is a directory");
    direct_ = !S_ISREG(st.st_mode) || under(target_, "/dev/") || under(target_, "/proc/");
    if (direct_) return; // FIFO, device, socket, /dev/stdout: written straight at publish(), never replaced
  } else if (errno != ENOENT) {
    cannotWrite(path_, std::strerror(errno));
  }
  std::string name = target_ + ".tmp.XXXXXX";
  // Signals wait while the temporary file is created and registered: one that ended the process between the two
  // would leave the file behind (seen with a Ctrl-C at the very start of a sweep).
  sigset_t all, before;
  sigfillset(&all);
  ::pthread_sigmask(SIG_BLOCK, &all, &before);
  fd_ = ::mkstemp(name.data());
  const int err = errno;
  if (fd_ >= 0) {
    tmp_ = name;
    tempSlot_ = registerTemp(tmp_);
  }
  ::pthread_sigmask(SIG_SETMASK, &before, nullptr);
  if (fd_ < 0) cannotWrite(path_, std::strerror(err));
}

SignalHandler removeTempsAndDie() { return onFatalSignal; }

namespace {

// What a path finally names, for comparing files: an existing file by device and inode (hard links, symlinks, "./x"
// and "x" all compare equal), a new one by its resolved directory and name. skip: stdout ("-") or a character device
// (/dev/null may take several outputs).
struct FileId {
  bool skip = false, exists = false;
  dev_t dev = 0;
  ino_t ino = 0;
  std::string resolved;
};

FileId fileId(const std::string& path) {
  FileId id;
  struct stat st;
  if (path == "-" || path.empty()) return id.skip = true, id;
  if (::stat(path.c_str(), &st) == 0) {
    id.skip = S_ISCHR(st.st_mode);
    id.exists = true, id.dev = st.st_dev, id.ino = st.st_ino;
    return id;
  }
  std::string target, why;
  if (!followLinks(path, target, why)) target = path;
  const size_t slash = target.find_last_of('/');
  const std::string name = slash == std::string::npos ? target : target.substr(slash + 1);
  char* dir = ::realpath(dirOf(target).c_str(), nullptr);
  id.resolved = (dir ? std::string(dir) : dirOf(target)) + "/" + name;
  std::free(dir);
  return id;
}

bool sameFile(const FileId& a, const FileId& b) {
  if (a.skip || b.skip || a.exists != b.exists) return false;
  return a.exists ? a.dev == b.dev && a.ino == b.ino : a.resolved == b.resolved;
}

} // namespace

void refuseSameFiles(const std::vector<FileArg>& outputs, const std::vector<FileArg>& inputs) {
  std::vector<FileId> ids;
  for (const FileArg& o : outputs) ids.push_back(fileId(o.path));
  for (size_t i = 0; i < outputs.size(); ++i) {
    if (outputs[i].path.empty()) continue;
    for (size_t k = 0; k < i; ++k)
      if (!outputs[k].path.empty() && sameFile(ids[k], ids[i]))
        throw UsageError(outputs[k].option + " " + quotePath(outputs[k].path) + " and " + outputs[i].option + " " +
                         quotePath(outputs[i].path) + " are the same file: one output would replace the other");
    for (const FileArg& in : inputs)
      if (!in.path.empty() && sameFile(fileId(in.path), ids[i]))
        throw UsageError(outputs[i].option + " " + quotePath(outputs[i].path) + " is the same file as " + in.option + " " +
                         quotePath(in.path) + ": writing it would replace the input");
  }
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) ::close(fd_);
  if (directFd_ >= 0) ::close(directFd_);
  if (!tmp_.empty() && !published_) ::unlink(tmp_.c_str());
  unregisterTemp(tempSlot_);
}

static void writeAll(int fd, const std::string& data, const std::string& path) {
  size_t done = 0;
  while (done < data.size()) {
    const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("writing " + quotePath(path) + " failed: " + std::strerror(errno));
    }
    done += static_cast<size_t>(n);
  }
}

void AtomicFile::write() {
  if (written_) return;
  written_ = true;
  if (fd_ < 0) return; // stdout or a straight write: at publish()
  writeAll(fd_, buffer_, path_);
  ::fchmod(fd_, 0644);
  const int rc = ::close(fd_);
  fd_ = -1;
  if (rc != 0) throw std::runtime_error("writing " + quotePath(path_) + " failed: " + std::strerror(errno));
}

void AtomicFile::publish() {
  write();
  if (published_) return;
  if (path_ == "-") {
    writeStdout(buffer_);
    flushStdout();
  } else if (direct_) {
    stream(buffer_);
    if (directFd_ < 0) stream(std::string()); // opens it: an empty report still reaches a FIFO's reader as EOF
    const int fd = directFd_;
    directFd_ = -1;
    if (::close(fd) != 0) throw std::runtime_error("writing " + quotePath(path_) + " failed: " + std::strerror(errno));
  } else if (std::rename(tmp_.c_str(), target_.c_str()) != 0) {
    throw std::runtime_error("writing " + quotePath(path_) + " failed: " + std::strerror(errno));
  } else {
    unregisterTemp(tempSlot_); // renamed: the name is the report now, a signal must not remove it
    tempSlot_ = -1;
  }
  published_ = true;
}

// Opens a FIFO, device or /dev/stdout for writing. A FIFO without a reader is waited for without blocking in open(),
// so a Ctrl-C is answered at once: it throws Interrupted when SIGINT arrives during the wait (with InterruptGuard; with
// the default action the signal ends the process and its temporary files, onFatalSignal).
static int openDirect(const std::string& target, const std::string& path) {
  struct stat st;
  if (::stat(target.c_str(), &st) != 0 || !S_ISFIFO(st.st_mode)) return ::open(target.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  const bool wasCancelled = InterruptGuard::flag()->load();
  for (;;) {
    const int fd = ::open(target.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC | O_NONBLOCK);
    if (fd >= 0) {
      ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
      return fd;
    }
    if (errno != ENXIO && errno != EINTR) return -1; // ENXIO: no reader yet
    if (!wasCancelled && InterruptGuard::flag()->load())
      throw Interrupted("interrupted while waiting for a reader of " + quotePath(path) + ": the reports were not written");
    ::usleep(20 * 1000);
  }
}

void AtomicFile::stream(const std::string& s) {
  if (path_ == "-") {
    writeStdout(s);
  } else if (direct_) {
    if (directFd_ < 0) directFd_ = openDirect(target_, path_);
    if (directFd_ < 0) throw std::runtime_error("writing " + quotePath(path_) + " failed: " + std::strerror(errno));
    writeAll(directFd_, s, path_);
  } else {
    writeAll(fd_, s, path_);
  }
}

void AtomicFile::unpublish() {
  if (published_ && !direct_ && !existed_ && path_ != "-") ::unlink(target_.c_str());
}

void commitAll(AtomicFile* const* files, size_t count) {
  for (size_t i = 0; i < count; ++i) files[i]->write();
  for (size_t i = 0; i < count; ++i) {
    try {
      files[i]->publish();
    } catch (...) {
      for (size_t k = 0; k < i; ++k) files[k]->unpublish();
      throw;
    }
  }
}

void writeStdout(const std::string& s) {
  if (s.empty()) return;
  if (std::fwrite(s.data(), 1, s.size(), stdout) != s.size())
    throw std::runtime_error(std::string("writing to stdout failed: ") + std::strerror(errno));
}

void flushStdout() {
  errno = 0;
  if (std::fflush(stdout) != 0 || std::ferror(stdout))
    throw std::runtime_error(std::string("writing to stdout failed: ") + std::strerror(errno ? errno : EIO));
}

std::string hex8(uint32_t v) {
  char buf[9];
  std::snprintf(buf, sizeof buf, "%08x", v);
  return buf;
}

std::string formatFloat(float f) {
  if (std::isnan(f)) return std::signbit(f) ? "-nan" : "nan";
  if (std::isinf(f)) return f < 0 ? "-inf" : "inf";
  char buf[40];
  for (int prec = 6; prec <= 9; ++prec) { // shortest of %.6g .. %.9g that reads back to the same float
    std::snprintf(buf, sizeof buf, "%.*g", prec, static_cast<double>(f));
    if (std::strtof(buf, nullptr) == f && std::signbit(std::strtof(buf, nullptr)) == std::signbit(f)) break;
  }
  return buf;
}

std::string formatNumber(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string fixed16(uint32_t v) { return "0x" + hex8(v); }

std::string fractionOf65536(int64_t units2) {
  bool neg = units2 < 0;
  uint64_t a = static_cast<uint64_t>(neg ? -units2 : units2);
  std::string s = (neg ? "-" : "") + std::to_string(a / 2) + (a % 2 ? ".5" : "");
  return s + "/65536";
}

UsageError::UsageError(const std::string& what) : std::runtime_error(printable(what, kMaxMessageBytes)) {}
UsageError::UsageError(const std::string& what, const std::string& lines)
    : std::runtime_error(printable(what, kMaxMessageBytes)) {
  size_t start = 0;
  while (start < lines.size() && details.size() < 64 * kMaxMessageBytes) {
    const size_t end = std::min(lines.find('\n', start), lines.size());
    const std::string line = lines.substr(start, end - start);
    if (line.find_first_not_of(" \t") != std::string::npos) details += printable(line, kMaxMessageBytes) + "\n";
    start = end + 1;
  }
}

// Length of the valid UTF-8 sequence at s[i] (no overlongs, no surrogates, <= U+10FFFF), 0 if invalid.
static size_t utf8Length(const std::string& s, size_t i) {
  const auto b = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(i);
  size_t n = c >= 0xc2 && c <= 0xdf ? 2 : c >= 0xe0 && c <= 0xef ? 3 : c >= 0xf0 && c <= 0xf4 ? 4 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  for (size_t k = 1; k < n; ++k)
    if ((b(i + k) & 0xc0) != 0x80) return 0;
  if (c == 0xe0 && b(i + 1) < 0xa0) return 0; // overlong
  if (c == 0xed && b(i + 1) >= 0xa0) return 0; // surrogate
  if (c == 0xf0 && b(i + 1) < 0x90) return 0; // overlong
  if (c == 0xf4 && b(i + 1) >= 0x90) return 0; // > U+10FFFF
  return n;
}

std::string printable(const std::string& s, size_t maxBytes) {
  std::string out;
  size_t i = 0;
  for (; i < s.size() && out.size() < maxBytes;) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
      ++i;
    } else if (const size_t n = c >= 0x80 ? utf8Length(s, i) : 0) {
      out.append(s, i, n);
      i += n;
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
      ++i;
    }
  }
  if (i < s.size()) out += "... (" + std::to_string(s.size()) + " bytes)";
  return out;
}

std::string quoteToken(const std::string& s) { return "'" + printable(s, 80) + "'"; }

std::string quotePath(const std::string& s) { return "'" + printable(s, std::string::npos) + "'"; }

std::string xmlEscape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
    case '&': o += "&amp;"; break;
    case '<': o += "&lt;"; break;
    case '>': o += "&gt;"; break;
    case '"': o += "&quot;"; break;
    default: o += c;
    }
  }
  return o;
}

} // namespace fftess::cli
