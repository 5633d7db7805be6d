// Progress of a long render on stderr: a bar on a terminal, a plain line every few seconds otherwise.
#pragma once
#include <chrono>
#include <cstdio>
#include <string>

namespace vibra::render {

/// Progress of a long render on stderr: a bar with frames, frames/s and ETA
/// when stderr is a terminal; a plain line every few seconds otherwise (logs,
/// CI); nothing when quiet.
class Progress {
 public:
  Progress(std::string what, long long total, bool quiet);
  void update(long long done);
  /// Prints the closing line (frames, seconds, frames/s).
  void finish(long long done);

 private:
  std::string what_;
  long long total_;
  bool quiet_, terminal_;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace vibra::render
