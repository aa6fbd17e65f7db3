// Progress bar and Ctrl-C handling (progress.h).
#include "progress.h"
#include "common.h"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <unistd.h>

namespace fftess::cli {
namespace {

std::atomic<bool> gCancel{false};
extern "C" void onSigint(int) {
  gCancel.store(true);
  std::signal(SIGINT, removeTempsAndDie()); // the second Ctrl-C kills, and removes temporary report files first
}

} // namespace

std::string duration(double s) {
  char b[32];
  if (!(s >= 0) || s > 1e7) return "--:--";
  const long t = std::lround(s);
  if (t >= 3600) std::snprintf(b, sizeof b, "%ld:%02ld:%02ld", t / 3600, t / 60 % 60, t % 60);
  else std::snprintf(b, sizeof b, "%ld:%02ld", t / 60, t % 60);
  return b;
}

Progress::Progress(const char* unit)
    : unit_(unit), tty_(::isatty(2) != 0), start_(std::chrono::steady_clock::now()), last_(start_) {}

double Progress::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::report(size_t done, size_t total) {
  const auto now = std::chrono::steady_clock::now();
  const double el = std::chrono::duration<double>(now - start_).count();
  const double since = std::chrono::duration<double>(now - last_).count();
  if (done < total && since < (tty_ ? 0.1 : 5.0)) return;
  last_ = now;
  const double rate = el > 0 ? static_cast<double>(done) / el : 0;
  const double eta = rate > 0 ? static_cast<double>(total - done) / rate : -1;
  char buf[200];
  if (tty_) {
    const int width = 30, fill = static_cast<int>(width * done / std::max<size_t>(total, 1));
    std::snprintf(buf, sizeof buf, "\r  [%s%s] %zu/%zu %s  %.1f/s  ETA %s ",
                  std::string(static_cast<size_t>(fill), '#').c_str(),
                  std::string(static_cast<size_t>(width - fill), '.').c_str(), done, total, unit_, rate,
                  duration(eta).c_str());
    barShown_ = true;
  } else {
    std::snprintf(buf, sizeof buf, "  sweep: %zu/%zu %s (%.0f%%), %.1f/s, ETA %s\n", done, total, unit_,
                  100.0 * static_cast<double>(done) / static_cast<double>(std::max<size_t>(total, 1)), rate,
                  duration(eta).c_str());
  }
  std::fputs(buf, stderr);
  std::fflush(stderr);
}

void Progress::finish() {
  if (barShown_) std::fputs("\n", stderr);
  barShown_ = false;
}

InterruptGuard::InterruptGuard() {
  gCancel.store(false);
  previous_ = std::signal(SIGINT, onSigint);
}

InterruptGuard::~InterruptGuard() { std::signal(SIGINT, previous_ == SIG_ERR ? SIG_DFL : previous_); }

const std::atomic<bool>* InterruptGuard::flag() { return &gCancel; }

} // namespace fftess::cli
