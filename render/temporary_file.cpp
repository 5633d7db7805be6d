#include "render/temporary_file.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <set>
#include <string>
#include <system_error>

#include "render/output_error.hpp"

namespace fs = std::filesystem;

namespace vibra::render {

namespace {
constexpr const char* kTag = ".vibra-tmp-";

fs::path directory_of(const fs::path& p) {
  fs::path dir = p.parent_path();
  return dir.empty() ? fs::path(".") : dir;
}

/// This machine's name, as temporaries carry it: processes on other machines
/// may share the directory (segments of one render on a cluster's shared
/// disk), and only this machine can tell whether its own PIDs are gone.
const std::string& host_name() {
  static const std::string name = [] {
    char text[256] = {};
    if (gethostname(text, sizeof text - 1) != 0 || !text[0]) return std::string("host");
    std::string host(text);
    for (char& c : host)
      if (c == '/' || c == '-') c = '_';
    return host;
  }();
  return name;
}
}  // namespace

void require_writable_directory(const fs::path& dir) {
  std::error_code ec;
  auto status = fs::status(dir, ec);
  if (!fs::exists(status))
    throw OutputError("directory '" + dir.string() + "' does not exist: create it or choose another output path");
  if (!fs::is_directory(status))
    throw OutputError("'" + dir.string() + "' is a file, not a directory: choose another output path");
  if (access(dir.c_str(), W_OK) != 0)
    throw OutputError("directory '" + dir.string() + "' is not writable: choose another output path");
}

// Once per directory and process: remove what killed runs left, and say so.
static void remove_stale_once(const fs::path& dir) {
  static std::mutex mutex;
  static std::set<fs::path> seen;
  std::error_code ec;
  const fs::path key = fs::weakly_canonical(dir, ec);
  {
    std::lock_guard lock(mutex);
    if (!seen.insert(ec ? dir : key).second) return;
  }
  for (const fs::path& stale : TemporaryFile::stale_in(dir)) {
    if (fs::remove(stale, ec))
      std::fprintf(stderr, "vibra: removed %s, a temporary left by a run that was killed\n", stale.c_str());
  }
}

TemporaryFile::TemporaryFile(fs::path final_path) : final_(std::move(final_path)) {
  if (final_.filename().empty())
    throw OutputError("output path '" + final_.string() + "' names a directory, not a file: add a file name");
  std::error_code ec;
  const fs::file_status status = fs::status(final_, ec);
  if (fs::is_directory(status))
    throw OutputError("output path '" + final_.string() + "' is a directory: give a file name");
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    // A device or pipe (/dev/null, /dev/stdout, a FIFO): write to it directly;
    // renaming over it would replace the device with a file.
    temp_ = final_;
    direct_ = true;
    return;
  }
  require_writable_directory(directory_of(final_));
  remove_stale_once(directory_of(final_));
  std::string name = ".";
  name += final_.filename().string();
  name += kTag;
  name += host_name() + "-" + std::to_string(getpid());
  temp_ = directory_of(final_) / name;
}

TemporaryFile::~TemporaryFile() {
  if (!done_) discard();
}

void TemporaryFile::commit() {
  if (direct_) {
    done_ = true;
    return;
  }
  std::error_code ec;
  fs::rename(temp_, final_, ec);
  if (ec) {
    discard();
    throw OutputError("cannot move the finished output to '" + final_.string() + "': " + ec.message());
  }
  done_ = true;
}

void TemporaryFile::discard() noexcept {
  done_ = true;
  if (direct_) return;
  std::error_code ec;
  fs::remove(temp_, ec);
}

std::vector<fs::path> TemporaryFile::stale_in(const fs::path& dir) {
  std::vector<fs::path> stale;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    std::string name = entry.path().filename().string();
    auto at = name.rfind(kTag);
    if (name.empty() || name[0] != '.' || at == std::string::npos) continue;
    const std::string owner = name.substr(at + std::strlen(kTag));  // HOST-PID
    const auto dash = owner.rfind('-');
    if (dash == std::string::npos || owner.substr(0, dash) != host_name()) continue;  // another machine's
    long pid = std::strtol(owner.c_str() + dash + 1, nullptr, 10);
    bool alive = pid > 0 && (kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM);
    if (!alive) stale.push_back(entry.path());
  }
  return stale;
}

}  // namespace vibra::render
