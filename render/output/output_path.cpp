// The one resolver of output paths: links, standard streams, devices, folders and the run's own inputs.
#include "render/output/output_path.hpp"

#include <unistd.h>

#include <cctype>
#include <system_error>

#include "core/input/input_files.hpp"
#include "render/output/created_directory.hpp"
#include "render/output/output_error.hpp"

namespace fs = std::filesystem;

namespace vibra::render {

namespace {
constexpr int kMostLinks = 40;  // as the kernel's ELOOP

std::string in_quotes(const fs::path& path) { return "'" + path.string() + "'"; }

/// The descriptor a path names (/dev/stdout 1, /dev/stderr 2, /dev/fd/N,
/// /proc/self/fd/N), or -1. Such a path is a stream whatever the descriptor
/// holds: a link in /proc to a regular file must not be renamed over.
int descriptor_named(const fs::path& path) {
  std::error_code ec;
  const fs::path p = fs::absolute(path, ec).lexically_normal();
  if (p == "/dev/stdin") return 0;
  if (p == "/dev/stdout") return 1;
  if (p == "/dev/stderr") return 2;
  const fs::path parent = p.parent_path();
  if (parent != "/dev/fd" && parent != "/proc/self/fd" && parent != "/proc/" + std::to_string(::getpid()) + "/fd")
    return -1;
  const std::string n = p.filename().string();
  if (n.empty() || n.size() > 9) return -1;
  for (char c : n)
    if (!std::isdigit(static_cast<unsigned char>(c))) return -1;
  return std::stoi(n);
}

/// Where a chain of symbolic links ends (the path itself when it is none),
/// or the descriptor it names on the way (`descriptor`, else -1).
fs::path follow_links(const fs::path& named, int& descriptor) {
  fs::path at = named;
  for (int hop = 0; hop <= kMostLinks; ++hop) {
    if ((descriptor = descriptor_named(at)) >= 0) return at;
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(at, ec))) return at;
    const fs::path to = fs::read_symlink(at, ec);
    if (ec) return at;
    at = to.is_absolute() ? to : at.parent_path() / to;
  }
  throw OutputError(in_quotes(named) + " is a loop of symbolic links: point it at a file, or choose another output name");
}
}  // namespace

std::string OutputTarget::shown() const {
  if (stream || file.empty() || fs::path(named).lexically_normal() == file.lexically_normal()) return named;
  return named + " -> " + file.string();
}

void refuse_input_as_output(const fs::path& output) {
  if (const auto input = input_at(output))
    throw OutputError("cannot write " + in_quotes(output) + ": this run reads it, as " + input->role + " " +
                      in_quotes(input->path) + ": choose another output name");
}

OutputTarget resolve_output(const std::string& named, const std::string& no_stream) {
  if (named.empty()) throw OutputError("the output path is empty: give a file name, e.g. -o out.mp4");
  OutputTarget target;
  target.named = named;
  const bool standard_output = named == "-";
  const fs::path end = standard_output ? fs::path() : follow_links(named, target.descriptor);
  std::error_code ec;
  const fs::file_status status = standard_output ? fs::file_status() : fs::status(end, ec);
  const bool device = fs::exists(status) && !fs::is_regular_file(status) && !fs::is_directory(status);
  if (standard_output || target.descriptor >= 0 || device) {
    if (!no_stream.empty())
      throw OutputError((standard_output ? std::string("- (standard output)") : in_quotes(named) + " is a pipe or device, which") +
                        " takes a stream; " + no_stream);
    target.stream = true;
    if (standard_output) target.descriptor = 1;
    if (target.descriptor < 0) target.device = end;
    return target;
  }
  if (fs::is_directory(status))
    throw OutputError(in_quotes(named) + (end == fs::path(named) ? "" : " (a link to " + in_quotes(end) + ")") +
                      " is a folder, not a file: give a file name, or move the folder away");
  refuse_input_as_output(end);
  fs::path parent = end.parent_path();
  require_creatable_directory(parent.empty() ? fs::path(".") : parent);
  target.file = end;
  return target;
}

fs::path resolve_output_file(const fs::path& path) { return resolve_output(path.string()).file; }

std::string lower_extension_of(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace vibra::render
