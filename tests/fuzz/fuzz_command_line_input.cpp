// The argv fuzz entry (fuzz_inputs.hpp): a whole command line run in this
// process as `vibra` runs it, with its files in a scratch folder and its
// standard output and error in memory. Every run is bounded: a tiny picture,
// and a watchdog that raises the stop flag after kBudget, as Ctrl-C would,
// so a run of 1e13 steps ends through the same path an interrupted one does.
#include <sys/mman.h>
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "cli/command_line.hpp"
#include "cli/run_command_line.hpp"
#include "core/input/input_files.hpp"
#include "core/stop_flag.hpp"
#include "fuzz_inputs.hpp"

namespace vibra::fuzz {
namespace {

constexpr auto kBudget = std::chrono::milliseconds(1500);
// How long a run may go on after the stop flag is raised (Ctrl-C promises
// an exit within a second); below libFuzzer's -timeout of 10 s, so the
// finding says which promise broke.
constexpr auto kStopGrace = std::chrono::seconds(6);
constexpr std::size_t kMaxArguments = 24, kMaxArgumentLength = 512;

/// Standard error as the process started: copied before libFuzzer's
/// -close_fd_mask or InMemory point descriptor 2 elsewhere, so a finding's
/// explanation is never written into memory that is thrown away.
const int real_stderr = ::dup(2);

void report(const std::string& text) {
  const std::string line = "vibra fuzz: " + text + "\n";
  for (std::size_t done = 0; done < line.size();) {
    const ssize_t n = ::write(real_stderr, line.data() + done, line.size() - done);
    if (n <= 0) return;
    done += static_cast<std::size_t>(n);
  }
}

/// Raises the stop flag (SIGINT) unless the run ends within kBudget, and
/// aborts, naming the command line, if it is still running kStopGrace later.
class Watchdog {
 public:
  explicit Watchdog(std::string command_line)
      : command_line_(std::move(command_line)), thread_([this] {
          std::unique_lock lock(mutex_);
          if (done_cv_.wait_for(lock, kBudget, [this] { return done_; })) return;
          record_stop_signal(SIGINT);
          if (done_cv_.wait_for(lock, kStopGrace, [this] { return done_; })) return;
          report("still running " + std::to_string(kStopGrace.count()) + " s after the stop flag (Ctrl-C): " +
                 command_line_);
          std::abort();
        }) {}
  ~Watchdog() {
    {
      std::lock_guard lock(mutex_);
      done_ = true;
    }
    done_cv_.notify_one();
    thread_.join();
    record_stop_signal(0);
  }

 private:
  std::string command_line_;
  std::mutex mutex_;
  std::condition_variable done_cv_;
  bool done_ = false;
  std::thread thread_;
};

/// Descriptor `fd` points into a memory file for the object's lifetime.
class InMemory {
 public:
  explicit InMemory(int fd) : fd_(fd), saved_(::dup(fd)), memory_(::memfd_create("vibra-fuzz", 0)) {
    std::fflush(nullptr);
    ::dup2(memory_, fd_);
  }
  ~InMemory() {
    std::fflush(nullptr);
    std::clearerr(fd_ == 1 ? stdout : stderr);
    ::dup2(saved_, fd_);
    ::close(saved_);
  }
  /// What was written (at most the first 64 KiB).
  std::string text() const {
    std::fflush(nullptr);
    std::string out(65536, '\0');
    const ssize_t n = ::pread(memory_, out.data(), out.size(), 0);
    out.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
    return out;
  }
  InMemory(const InMemory&) = delete;
  InMemory& operator=(const InMemory&) = delete;
  void close_memory() { ::close(memory_); }

 private:
  int fd_, saved_, memory_;
};

/// A folder of its own, the working directory while a run lasts; emptied after.
class ScratchFolder {
 public:
  ScratchFolder() : previous_(std::filesystem::current_path()) {
    static const std::filesystem::path folder = [] {
      std::string name = (std::filesystem::temp_directory_path() / "vibra_fuzz_argv_XXXXXX").string();
      if (!::mkdtemp(name.data())) std::abort();
      return std::filesystem::path(name);
    }();
    folder_ = folder;
    std::filesystem::current_path(folder_);
  }
  ~ScratchFolder() {
    std::filesystem::current_path(previous_);
    std::error_code ignored;
    for (const auto& entry : std::filesystem::directory_iterator(folder_, ignored))
      std::filesystem::remove_all(entry.path(), ignored);
  }

 private:
  std::filesystem::path previous_, folder_;
};

/// The input's lines as arguments: the first names the command. Arguments
/// that could reach a file outside the scratch folder (any '/'), or that
/// would replace the bounds added below, are dropped.
std::vector<std::string> arguments_of(std::string_view text) {
  std::vector<std::string> args;
  std::size_t start = 0;
  while (start < text.size() && args.size() < kMaxArguments) {  // a final newline ends the last argument
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string arg(text.substr(start, std::min(end - start, kMaxArgumentLength)));
    start = end + 1;
    const bool bound = arg == "-o" || arg == "--output" || arg == "--size" || arg == "--threads" || arg == "--format" ||
                       arg == "--rate" || arg.starts_with("-o") || arg.starts_with("--output=") ||
                       arg.starts_with("--size=") || arg.starts_with("--threads=") || arg.starts_with("--format=") ||
                       arg.starts_with("--rate=");
    if (arg.find('/') != std::string::npos || arg.find('\0') != std::string::npos || bound) continue;
    args.push_back(arg);
    if (end == text.size()) break;
  }
  return args;
}

/// The bounds and the output for `command`: a 64x36 picture, one thread,
/// files in the scratch folder; `pick` chooses among the kinds of output.
std::vector<std::string> bounds_for(const std::string& command, unsigned pick) {
  if (command == "solve") return pick % 2 ? std::vector<std::string>{"-o", "out.csv"} : std::vector<std::string>{};
  if (command == "ascii") return {};
  if (command == "plot") return {"--size", "240x160", "-o", "plot.png"};
  if (command == "analyze") return {"--size", "240x160", "-o", "figure.png"};
  std::vector<std::string> render = {"--size", "64x36", "--threads", "1", "-q"};
  const std::vector<std::vector<std::string>> outputs = {
      {"-o", "-", "--format", "y4m"}, {"-o", "still.png"}, {"-o", "frames/f_%03d.png"}, {"-o", "page.html"},
      {"-o", "still.svg"},            {"-o", "clip.mp4"}};
  const auto& out = outputs[pick % outputs.size()];
  render.insert(render.end(), out.begin(), out.end());
  return render;
}

}  // namespace

void command_line(std::string_view text) {
  std::vector<std::string> args = arguments_of(text);
  if (args.empty()) return;
  const std::string command = args.front();
  if (command != "solve" && command != "render" && command != "ascii" && command != "plot" && command != "analyze") return;
  unsigned pick = 0;
  for (const char c : text) pick = pick * 31 + static_cast<unsigned char>(c);
  for (auto& extra : bounds_for(command, pick)) args.push_back(extra);

  std::vector<char*> argv{const_cast<char*>("vibra")};
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  int code;
  std::string messages;
  {
    ScratchFolder folder;
    InMemory out(1), err(2);
    forget_input_files();
    quiet_long_work(true);
    cli::remember_command_line(static_cast<int>(argv.size() - 1), argv.data());
    {
      std::string shown = "vibra";
      for (const auto& a : args) shown += " '" + a + "'";
      Watchdog watchdog(shown);
      code = cli::run_command_line(static_cast<int>(argv.size() - 1), argv.data());
    }
    messages = err.text();
    out.close_memory();
    err.close_memory();
  }
  // What every run must keep: a known exit code, and an error is one line.
  if (code != 0 && code != 2 && code != 128 + SIGINT) {
    report("exit code " + std::to_string(code) + ": " + messages);
    std::abort();
  }
  if (code == 2) {
    const std::size_t last = messages.rfind("vibra: error: ");
    const bool one_line = last != std::string::npos && messages.find('\n', last) == messages.size() - 1 &&
                          messages.size() - last <= 320;
    if (!one_line) {
      report("not one error line: " + messages);
      std::abort();
    }
  }
}

}  // namespace vibra::fuzz
