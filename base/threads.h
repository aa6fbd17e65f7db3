// fftess base: running one piece of work on several threads, where starting a thread may fail.
//
// std::thread's constructor throws std::system_error when the system refuses a thread (EAGAIN: too many threads, no
// memory for a stack). A pool that lets that exception unwind past started, joinable threads ends the program in
// std::terminate ("terminate called without an active exception", exit 134): issue 42 saw it with `-j 100000`. The
// helper here stops and joins what it started and reports the failure as one exception with one message, which the
// cli turns into exit 3.
#pragma once

#include <cstddef>
#include <exception>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

namespace fftess {

// The most threads a caller may ask of fftess's pools (the cli refuses more with exit 2 naming --threads). Far above
// any machine's cores; it bounds what a typo can ask for.
constexpr int kMaxThreads = 1024;

// Runs work(t) for t = 1 .. threads - 1 on new threads and work(0) on this one, then joins them all. threads < 1 runs
// work(0) alone. If a thread cannot be started, stop() is called (it must make the running work(t) return soon),
// work(0) is not run, the started threads are joined, and std::runtime_error("could not start thread K of N: REASON")
// is thrown. An exception from work(0) calls stop(), joins the others and is rethrown; one escaping work(t) on a new
// thread terminates, as with std::thread (catch it inside work).
// - work: callable as work(int); called concurrently from every thread.
// - stop: callable as stop(); called at most once, on this thread, only when a start failed or work(0) threw.
template <class Work, class Stop>
void runOnThreads(int threads, Work&& work, Stop&& stop) {
  std::vector<std::thread> pool;
  if (threads > 1) pool.reserve(static_cast<size_t>(threads) - 1);
  std::string failure;
  for (int t = 1; t < threads; ++t) {
    try {
      pool.emplace_back([&work, t] { work(t); });
    } catch (const std::system_error& e) {
      failure = "could not start thread " + std::to_string(t + 1) + " of " + std::to_string(threads) + ": " + e.what() +
                " (fewer threads: --threads)";
      break;
    }
  }
  std::exception_ptr error; // one thrown by work(0): the others are stopped and joined before it goes on
  if (failure.empty()) {
    try {
      work(0);
    } catch (...) {
      error = std::current_exception();
      stop();
    }
  } else {
    stop();
  }
  for (std::thread& th : pool) th.join();
  if (error) std::rethrow_exception(error);
  if (!failure.empty()) throw std::runtime_error(failure);
}

} // namespace fftess
