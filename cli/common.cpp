#include "common.h"

#include <cerrno>
#include <cstdlib>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sys/stat.h>
#include <unistd.h>

namespace fftess::cli {

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {}

AtomicFile::~AtomicFile() = default; // nothing is on disk until commit(): the temp file only lives inside commit()

void AtomicFile::commit() {
  if (committed_) return;
  committed_ = true;
  if (path_ == "-") {
    writeStdout(buffer_);
    return;
  }
  std::string tmpl = path_ + ".tmp.XXXXXX";
  std::string name(tmpl);
  int fd = ::mkstemp(name.data());
  if (fd < 0)
    throw UsageError("cannot write '" + path_ + "': " + std::strerror(errno));
  size_t done = 0;
  while (done < buffer_.size()) {
    ssize_t n = ::write(fd, buffer_.data() + done, buffer_.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      int e = errno;
      ::close(fd);
      ::unlink(name.c_str());
      throw std::runtime_error("writing '" + path_ + "' failed: " + std::strerror(e));
    }
    done += static_cast<size_t>(n);
  }
  ::fchmod(fd, 0644);
  if (::close(fd) != 0) {
    int e = errno;
    ::unlink(name.c_str());
    throw std::runtime_error("writing '" + path_ + "' failed: " + std::strerror(e));
  }
  if (std::rename(name.c_str(), path_.c_str()) != 0) {
    int e = errno;
    ::unlink(name.c_str());
    throw UsageError("cannot write '" + path_ + "': " + std::strerror(e));
  }
}

void writeStdout(const std::string& s) {
  if (s.empty()) return;
  if (std::fwrite(s.data(), 1, s.size(), stdout) != s.size())
    throw std::runtime_error(std::string("writing to stdout failed: ") + std::strerror(errno));
}

uint32_t floatBits(float f) {
  uint32_t b;
  std::memcpy(&b, &f, sizeof b);
  return b;
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

std::string fixed16(uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08x", v);
  return buf;
}

std::string fractionOf65536(int64_t units2) {
  bool neg = units2 < 0;
  uint64_t a = static_cast<uint64_t>(neg ? -units2 : units2);
  std::string s = (neg ? "-" : "") + std::to_string(a / 2) + (a % 2 ? ".5" : "");
  return s + "/65536";
}

std::string quoteToken(const std::string& s) {
  std::string out = "'";
  for (unsigned char c : s) {
    if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "'";
}

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
