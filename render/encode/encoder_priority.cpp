// Lowers the encoder threads' priority so the drawing thread keeps its core.
#include "render/encode/encoder_priority.hpp"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace vibra::render {

namespace {
/// How many steps of nice the encoder's threads give way by.
constexpr int kNiceSteps = 5;

/// The ids of this process's threads (none where /proc is not mounted).
std::vector<pid_t> threads_now() {
  std::vector<pid_t> out;
  std::error_code error;
  for (std::filesystem::directory_iterator it("/proc/self/task", error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (!name.empty() && std::all_of(name.begin(), name.end(), [](char c) { return c >= '0' && c <= '9'; }))
      out.push_back(static_cast<pid_t>(std::stol(name)));
  }
  std::sort(out.begin(), out.end());
  return out;
}

void lower(pid_t thread) {
  errno = 0;
  const int nice = getpriority(PRIO_PROCESS, static_cast<id_t>(thread));
  if (errno != 0) return;
  setpriority(PRIO_PROCESS, static_cast<id_t>(thread), std::min(19, nice + kNiceSteps));  // best effort
}
}  // namespace

EncoderPriority::EncoderPriority() : before_(threads_now()) {}

void EncoderPriority::lower_started_since() const {
  for (pid_t thread : threads_now())
    if (!std::binary_search(before_.begin(), before_.end(), thread)) lower(thread);
}

void EncoderPriority::lower_this_thread() { lower(static_cast<pid_t>(syscall(SYS_gettid))); }

}  // namespace vibra::render
