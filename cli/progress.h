// Progress and interrupts for long commands (sweep): a bar on a terminal, a plain line every few seconds otherwise;
// Ctrl-C asks the running work to stop.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <string>

namespace fftess::cli {

// "m:ss" or "h:mm:ss"; "--:--" for a negative or absurd value.
std::string duration(double seconds);

// Prints progress of `total` units of work on stderr. report() may be called often: it prints at most every 0.1 s on
// a terminal (a bar with rate and ETA, redrawn in place) and every 5 s otherwise (one line each), and always for the
// last unit. finish() ends a bar with a newline. Not thread-safe: callers serialise (verify's sweep does).
class Progress {
public:
  explicit Progress(const char* unit);
  void report(size_t done, size_t total);
  void finish();
  double elapsed() const; // seconds since construction

private:
  const char* unit_;
  bool tty_;
  bool barShown_ = false;
  std::chrono::steady_clock::time_point start_, last_;
};

// While an instance lives, the first SIGINT sets flag() (the work stops and reports are still written); the second
// one kills the process (after the first, SIGINT removes the temporary report files and takes its default action).
// flag() is also watched where the process would otherwise wait with the signal unanswered (AtomicFile waiting for a
// FIFO's reader). The previous handler comes back on destruction.
class InterruptGuard {
public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
  static const std::atomic<bool>* flag();

private:
  void (*previous_)(int);
};

} // namespace fftess::cli
