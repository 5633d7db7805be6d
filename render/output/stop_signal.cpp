// Cooperative cancellation for long work: SIGINT/SIGTERM set a flag that render and output loops poll between frames, so they can stop cleanly, remove their temporary files and exit with 128 + signal.
#include "render/output/stop_signal.hpp"

#include <csignal>

namespace vibra::render {
namespace {
extern "C" void record_stop(int sig) { record_stop_signal(sig); }
}  // namespace

void install_stop_handlers() {
  struct sigaction action {};
  action.sa_handler = record_stop;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

ScopedStopHandlers::ScopedStopHandlers() {
  sigaction(SIGINT, nullptr, &previous_[0]);
  sigaction(SIGTERM, nullptr, &previous_[1]);
  record_stop_signal(0);
  install_stop_handlers();
}

ScopedStopHandlers::~ScopedStopHandlers() {
  sigaction(SIGINT, &previous_[0], nullptr);
  sigaction(SIGTERM, &previous_[1], nullptr);
  if (const int sig = take_stop_signal()) std::raise(sig);
}

}  // namespace vibra::render
