// The one stop flag every long loop polls (solver steps, pre-passes, analyses, drawing, encoding, concat).
// SIGINT and SIGTERM set it (render/output/stop_signal.hpp installs the
// handlers), and the loop that sees it throws Interrupted, so the run removes
// its temporaries and exits with 128 + signal. In core so that the solver
// itself can look at it.
#pragma once
#include <string>

namespace vibra {

/// Thrown by loops that noticed a stop request; the CLI maps it to 128 + signal.
struct Interrupted {
  int signal;
  const char* outcome = "no partial output was kept";  // what the user finds afterwards
};

/// Records a stop request (async-signal-safe: one atomic store).
void record_stop_signal(int signal);

/// The signal number that asked us to stop, or 0.
int stop_signal();

/// The signal recorded, cleared in the same atomic step (0 if none).
int take_stop_signal();

/// Throws Interrupted if a stop was requested, or if the poll set by
/// set_stop_poll reports a signal (which is then recorded).
void throw_if_stop_requested();

/// A host that handles signals itself (the Python module: a signal Python
/// has noted but not yet acted on, or one `_thread.interrupt_main()` sends)
/// is asked at every look at the flag; the poll returns the signal or 0, and
/// must be cheap and safe on any thread. nullptr: none (the default).
using StopPoll = int (*)();
void set_stop_poll(StopPoll);

/// For long runs of known length: after about 2 s of a run of `total` steps
/// (1e8 or more; not an endless one), a line on stderr every 10 s or so,
/// "vibra: step N of M (P%), about S s left", unless quiet_long_work.
void report_long_work(long long done, long long total);
/// Seconds left in the unit a person reads: "40 s", "12 min", "3.5 h",
/// "9 days", "2.7e+02 years" (report_long_work's estimate).
std::string time_left_text(double seconds);
/// No progress lines (-q, the Python module, the fuzz targets).
void quiet_long_work(bool quiet);

/// How often hot loops look at the flag: every 1024th step. A step costs
/// nanoseconds to a millisecond (a formula's energy by quadrature on every
/// row, the sanitizers), so this is a stop within a second of Ctrl-C for all
/// of them, and the look (a load and a compare) is nothing beside a step.
inline constexpr long long kStopPollEvery = 1024;
static_assert((kStopPollEvery & (kStopPollEvery - 1)) == 0, "poll_stop masks the counter: a power of two");

/// For hot loops: looks at the flag every kStopPollEvery-th value of
/// `counter`, so a loop of tiny steps pays one compare per step; there also
/// reports the progress of a long run of `total` steps.
inline void poll_stop(long long counter, long long total = 0) {
  if ((counter & (kStopPollEvery - 1)) == 0) [[unlikely]] {
    throw_if_stop_requested();
    if (total >= 100'000'000) report_long_work(counter, total);
  }
}

}  // namespace vibra
