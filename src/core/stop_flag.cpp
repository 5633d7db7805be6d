// The one stop flag: the signal the handler recorded, checked by long loops, and their progress reports.
#include "core/stop_flag.hpp"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <limits>

namespace vibra {

namespace {
std::atomic<int> g_stop_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "stored from a signal handler");
std::atomic<bool> g_quiet{false};
std::atomic<StopPoll> g_poll{nullptr};
}  // namespace

void record_stop_signal(int signal) { g_stop_signal.store(signal, std::memory_order_relaxed); }

int stop_signal() { return g_stop_signal.load(std::memory_order_relaxed); }

int take_stop_signal() { return g_stop_signal.exchange(0); }

void throw_if_stop_requested() {
  if (const int sig = stop_signal()) throw Interrupted{sig};
  if (const StopPoll poll = g_poll.load(std::memory_order_relaxed))
    if (const int sig = poll()) {
      record_stop_signal(sig);  // every other loop, on every thread, stops too
      throw Interrupted{sig};
    }
}

void set_stop_poll(StopPoll poll) { g_poll.store(poll); }

void quiet_long_work(bool quiet) { g_quiet = quiet; }

void report_long_work(long long done, long long total) {
  using Clock = std::chrono::steady_clock;
  // One run at a time is timed: a new one starts when the count goes back.
  thread_local long long last_done = std::numeric_limits<long long>::max(), first_done = 0;
  thread_local Clock::time_point start, next_line;
  const Clock::time_point now = Clock::now();
  if (done < last_done) {
    first_done = done;
    start = now;
    next_line = now + std::chrono::seconds(2);
  }
  last_done = done;
  if (g_quiet || total == std::numeric_limits<long long>::max() || now < next_line || done <= first_done) return;
  next_line = now + std::chrono::seconds(10);
  const double seconds = std::chrono::duration<double>(now - start).count();
  const double left = seconds * double(total - done) / double(done - first_done);
  std::fprintf(stderr, "vibra: step %lld of %lld (%.1f%%), about %s left; Ctrl-C stops it\n", done, total,
               100.0 * double(done) / double(total), time_left_text(left).c_str());
}

std::string time_left_text(double seconds) {
  constexpr double kMinute = 60, kHour = 3600, kDay = 86400, kYear = 365.25 * kDay;
  char text[48];
  if (seconds < 2 * kMinute) std::snprintf(text, sizeof text, "%.0f s", seconds);
  else if (seconds < 2 * kHour) std::snprintf(text, sizeof text, "%.0f min", seconds / kMinute);
  else if (seconds < 2 * kDay) std::snprintf(text, sizeof text, "%.1f h", seconds / kHour);
  else if (seconds < kYear) std::snprintf(text, sizeof text, "%.0f days", seconds / kDay);
  else {
    std::snprintf(text, sizeof text, "%.2g", seconds / kYear);
    return text + std::string(text == std::string("1") ? " year" : " years");
  }
  return text;
}

}  // namespace vibra
