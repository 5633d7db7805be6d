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

ScopedStopHandlers::ScopedStopHandlers() {
  sigaction(SIGINT, nullptr, &previous_[0]);
  sigaction(SIGTERM, nullptr, &previous_[1]);
  g_stop_signal.store(0);
  install_stop_handlers();
}

ScopedStopHandlers::~ScopedStopHandlers() {
  sigaction(SIGINT, &previous_[0], nullptr);
  sigaction(SIGTERM, &previous_[1], nullptr);
  if (const int sig = g_stop_signal.exchange(0)) std::raise(sig);
}

}  // namespace vibra::render
