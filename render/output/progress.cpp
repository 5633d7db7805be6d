// Progress of a long render on stderr: a bar on a terminal, a plain line every few seconds otherwise.
#include "render/output/progress.hpp"

#include <unistd.h>

#include <algorithm>

namespace vibra::render {

namespace {
double seconds(std::chrono::steady_clock::duration d) { return std::chrono::duration<double>(d).count(); }
}  // namespace

Progress::Progress(std::string what, long long total, bool quiet)
    : what_(std::move(what)), total_(total), quiet_(quiet), terminal_(isatty(STDERR_FILENO) == 1) {
  start_ = last_ = std::chrono::steady_clock::now();
}

void Progress::update(long long done) {
  if (quiet_) return;
  const auto now = std::chrono::steady_clock::now();
  const double since = seconds(now - last_);
  if (since < (terminal_ ? 0.1 : 5.0)) return;
  last_ = now;
  const double elapsed = seconds(now - start_), rate = done / std::max(elapsed, 1e-9);
  const double eta = rate > 0 ? (total_ - done) / rate : 0;
  if (terminal_) {
    const int width = 30, filled = total_ > 0 ? int(width * done / total_) : 0;
    std::string bar(filled, '#');
    bar.resize(width, '.');
    std::fprintf(stderr, "\r%s [%s] %lld/%lld frames  %.1f frames/s  ETA %.0f s ", what_.c_str(), bar.c_str(), done,
                 total_, rate, eta);
  } else {
    std::fprintf(stderr, "%s: %lld/%lld frames, %.1f frames/s, ETA %.0f s\n", what_.c_str(), done, total_, rate, eta);
  }
  std::fflush(stderr);
}

void Progress::finish(long long done) {
  if (quiet_) return;
  const double elapsed = seconds(std::chrono::steady_clock::now() - start_);
  std::fprintf(stderr, "%s%s: %lld frames in %.2f s (%.1f frames/s)\n", terminal_ ? "\r\033[K" : "", what_.c_str(), done,
               elapsed, done / std::max(elapsed, 1e-9));
}

}  // namespace vibra::render
