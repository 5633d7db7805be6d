// Runs the chapter's commands in forked copies of this process, N at a time, each in the site's folder.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace vibra::cli {

/// One vibra command of the chapter: its arguments after `vibra`, and the
/// file in the folder that keeps its standard output.
struct ChapterJob {
  std::vector<std::string> args;
  std::string output_text;  ///< e.g. "ex1.9-1.txt"; removed when the command printed nothing
  std::string label;        ///< what progress names, e.g. "Exercise 1.9"
};

/// Runs every job as `vibra ARGS` would, without starting the executable
/// again: a forked copy of this process enters the CLI's own
/// run_command_line from inside `folder`, so -o names land there, with its
/// standard output in the job's file and its messages kept apart. At most
/// `parallel` at once, in order. Progress on stderr when it is a terminal
/// (unless quiet). A job that fails throws OutputError with its command and
/// its one line; a stop request (Ctrl-C) passes on to the running jobs, waits
/// for them, and throws Interrupted. Either way the caller removes `folder`.
void run_chapter_jobs(const std::vector<ChapterJob>& jobs, const std::filesystem::path& folder, int parallel,
                      bool quiet);

/// `vibra ARG...`, each argument quoted for a POSIX shell where it needs it.
std::string shown_command(const std::vector<std::string>& args);

}  // namespace vibra::cli
