// A small process pool for `vibra chapter`: fork, run the CLI in the child, collect exit codes, stop on Ctrl-C.
#include "cli/chapter/chapter_jobs.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <thread>

#include "cli/command_line.hpp"
#include "cli/run_command_line.hpp"
#include "core/input/quoted_value.hpp"
#include "render/output/output_error.hpp"
#include "render/output/standard_output.hpp"
#include "render/output/stop_signal.hpp"

namespace vibra::cli {

namespace fs = std::filesystem;

namespace {
/// A job's messages (stderr) while it runs; read when it fails, then removed.
fs::path messages_file(const fs::path& folder, size_t job) {
  return folder / (".job-" + std::to_string(job) + ".messages");
}

/// In the forked child: becomes `vibra ARGS` run from `folder`; never returns.
[[noreturn]] void run_in_child(const ChapterJob& job, const fs::path& folder, size_t index) {
  const int out = ::open((folder / job.output_text).c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int err = ::open(messages_file(folder, index).c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (out < 0 || err < 0 || ::dup2(out, 1) < 0 || ::dup2(err, 2) < 0 || ::chdir(folder.c_str()) != 0) ::_exit(125);
  ::close(out), ::close(err);
  std::vector<std::string> words{"vibra"};
  words.insert(words.end(), job.args.begin(), job.args.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  remember_command_line(static_cast<int>(words.size()), argv.data());  // pages record `vibra ...`, no path
  int code = run_command_line(static_cast<int>(words.size()), argv.data());
  const int error = render::close_standard_output();
  if (error != 0 && code == 0) {
    std::fprintf(stderr, "vibra: error: writing standard output: %s\n", std::strerror(error));
    code = 2;
  }
  std::fflush(stderr);
  ::_exit(code);
}

/// The last line of a failed job's messages, for the one line that reports it.
std::string last_message(const fs::path& file) {
  std::ifstream in(file);
  std::string line, last = "no message";
  for (int lines = 0; lines < 10000 && std::getline(in, line); ++lines)
    if (!line.empty()) last = line;
  const std::string prefix = "vibra: error: ";  // the command's own line, without a second "vibra: error:"
  return last.rfind(prefix, 0) == 0 ? last.substr(prefix.size()) : last;
}

struct Running {
  pid_t pid;
  size_t job;
};

/// A line on a terminal: how many commands are done, and one that runs.
void show_progress(size_t done, size_t total, const std::string& label) {
  std::fprintf(stderr, "\r\033[Kvibra chapter: %zu/%zu commands done; %s", done, total, label.c_str());
  std::fflush(stderr);
}

/// Ends the running jobs with `signal` and waits for each.
void end_jobs(std::vector<Running>& running, int signal) {
  for (const Running& r : running) ::kill(r.pid, signal);
  for (const Running& r : running) {
    int status = 0;
    while (::waitpid(r.pid, &status, 0) < 0 && errno == EINTR) {
    }
  }
  running.clear();
}

/// The exit code of a finished job.
int exit_code(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status); }

/// A job ended: on failure the others are ended and OutputError names it.
void check_finished(const ChapterJob& job, int status, const fs::path& messages, std::vector<Running>& others) {
  if (exit_code(status) != 0) {
    end_jobs(others, SIGTERM);
    throw render::OutputError("chapter: '" + quoted_value(shown_command(job.args), 120) + "' failed (exit " +
                              std::to_string(exit_code(status)) + "): " + last_message(messages));
  }
  fs::remove(messages);
}

/// Reaps one finished job, if any; returns its index or npos.
size_t reap_one(std::vector<Running>& running, const std::vector<ChapterJob>& jobs, const fs::path& folder) {
  for (size_t i = 0; i < running.size(); ++i) {
    int status = 0;
    if (::waitpid(running[i].pid, &status, WNOHANG) != running[i].pid) continue;
    const size_t job = running[i].job;
    running.erase(running.begin() + static_cast<long>(i));
    if (const int signal = render::stop_signal()) {  // it was stopped with us: say so, not that it failed
      end_jobs(running, signal);
      throw render::Interrupted{signal, "no site was written"};
    }
    check_finished(jobs[job], status, messages_file(folder, job), running);
    return job;
  }
  return std::string::npos;
}
}  // namespace

std::string shown_command(const std::vector<std::string>& args) {
  std::string line = "vibra";
  for (const std::string& arg : args) {
    line += ' ';
    line += shell_quoted(arg);
  }
  return line;
}

void run_chapter_jobs(const std::vector<ChapterJob>& jobs, const fs::path& folder, int parallel, bool quiet) {
  const bool terminal = !quiet && ::isatty(STDERR_FILENO) == 1;
  std::vector<Running> running;
  size_t next = 0, done = 0;
  std::fflush(nullptr);  // nothing buffered is written twice by a child
  while (done < jobs.size()) {
    if (const int signal = render::stop_signal()) {
      end_jobs(running, signal);
      throw render::Interrupted{signal, "no site was written"};
    }
    while (running.size() < static_cast<size_t>(parallel) && next < jobs.size()) {
      const pid_t pid = ::fork();
      if (pid < 0) {
        end_jobs(running, SIGTERM);
        throw render::OutputError(std::string("chapter: cannot start a job: ") + std::strerror(errno));
      }
      if (pid == 0) run_in_child(jobs[next], folder, next);
      running.push_back({pid, next++});
    }
    const size_t finished = reap_one(running, jobs, folder);
    if (finished == std::string::npos) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      continue;
    }
    ++done;
    if (terminal) show_progress(done, jobs.size(), jobs[finished].label);
  }
  if (terminal) std::fprintf(stderr, "\r\033[K");
}

}  // namespace vibra::cli
