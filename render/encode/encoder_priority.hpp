// Lowers the encoder threads' priority so the drawing thread keeps its core.
#pragma once
#include <sys/types.h>

#include <vector>

namespace vibra::render {

/// The encoder's threads yield to the drawing thread. On a machine with
/// fewer cores than runnable threads (two cores: the drawing thread and
/// x264's five), the scheduler shares the cores evenly, and the drawing
/// thread, the one that cannot be split, runs at half speed while the
/// encoder works ahead of it on frames already queued. With the encoder's
/// threads five steps of nice lower in priority, drawing runs whenever it
/// has work and the encoder takes every cycle left over: when drawing is the
/// slower, frames come faster; when encoding is, drawing waits on the full
/// queue as before and the encoder has the machine.
///
/// Notes the threads that exist; lower_started_since() then lowers the
/// priority of those started since (the encoder's, started by
/// avcodec_open2). Lowering one's own priority needs no privilege; where it
/// fails nothing changes.
class EncoderPriority {
 public:
  EncoderPriority();
  void lower_started_since() const;
  /// Lowers the calling thread's priority (the thread that feeds the encoder).
  static void lower_this_thread();

 private:
  std::vector<pid_t> before_;
};

}  // namespace vibra::render
