#include "render/stop_signal.hpp"

#include <atomic>
#include <csignal>

namespace vibra::render {
namespace {
std::atomic<int> g_stop_signal{0};
extern "C" void record_stop(int sig) { g_stop_signal.store(sig); }
}  // namespace

void install_stop_handlers() {
  struct sigaction action {};
  action.sa_handler = record_stop;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int stop_signal() { return g_stop_signal.load(std::memory_order_relaxed); }

void throw_if_stop_requested() {
  if (int sig = stop_signal()) throw Interrupted{sig};
}

}  // namespace vibra::render
