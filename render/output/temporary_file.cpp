// TemporaryFile and TemporaryDirectory: outputs written under temporary names and put in place only on success.
#include "render/output/temporary_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <set>
#include <string>
#include <system_error>

#include "render/output/output_error.hpp"
#include "render/output/output_path.hpp"
#include "render/output/stop_signal.hpp"
#include "render/output/ownership_manifest.hpp"
#include "render/output/temporary_claim.hpp"

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

std::string said_of_output(std::string message, const std::string& output) {
  for (size_t from = 0, at; (at = message.find(kTag, from)) != std::string::npos;) {
    const size_t open = message.rfind('\'', at), close = message.find('\'', at);
    if (open == std::string::npos || close == std::string::npos) break;
    message.replace(open, close + 1 - open, "'" + output + "'");
    from = open + output.size() + 2;  // past the name given, which may hold the tag itself
  }
  return message;
}

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
    // Only what vibra can prove it wrote: a name is no proof (temporary_claim.hpp).
    if (provably_vibras_temporary(stale) && fs::remove_all(stale, ec) > 0)
      std::fprintf(stderr, "vibra: removed %s, a temporary left by a run that was killed\n", stale.c_str());
  }
}

/// `.NAME.vibra-tmp-HOST-PID` in `dir`, after removing what killed runs left there.
static fs::path temporary_name(const fs::path& dir, const std::string& name) {
  remove_stale_once(dir);
  return dir / ("." + name + kTag + host_name() + "-" + std::to_string(getpid()));
}

TemporaryFile::TemporaryFile(const fs::path& final_path)
    : final_(resolve_output_file(final_path)), parents_(directory_of(final_)) {  // parents_ checks it is writable
  temp_ = temporary_name(directory_of(final_), final_.filename().string());
}

TemporaryFile::~TemporaryFile() {
  if (!done_) discard();
}

void TemporaryFile::commit() {
  throw_if_stop_requested();  // a run asked to stop keeps nothing, however far it got
  std::error_code ec;
  fs::rename(temp_, final_, ec);
  if (ec) {
    discard();
    throw OutputError("cannot move the finished output to '" + final_.string() + "': " + ec.message());
  }
  done_ = true;
  parents_.keep();
}

void TemporaryFile::discard() noexcept {
  done_ = true;
  std::error_code ec;
  fs::remove(temp_, ec);
}

TemporaryDirectory::TemporaryDirectory(const fs::path& location, const std::string& name)
    : parents_(location), location_(location.empty() ? fs::path(".") : location) {
  path_ = temporary_name(location_, name);
  std::error_code ec;
  // This process's own, from an earlier output of the same name; never anything it cannot prove its own.
  if (fs::exists(fs::symlink_status(path_, ec)) && provably_vibras_temporary(path_)) fs::remove_all(path_, ec);
  if (!fs::create_directory(path_, ec))
    throw OutputError("cannot create the folder '" + path_.string() + "': " + (ec ? ec.message() : "it exists") +
                      ": choose another output path");
  write_claim(path_);
}

void TemporaryDirectory::seal() {
  std::error_code ec;
  fs::remove(path_ / kClaimName, ec);
  write_manifest(path_);
}

TemporaryDirectory::~TemporaryDirectory() {
  if (done_) return;
  std::error_code ec;
  fs::remove_all(path_, ec);
}

void TemporaryDirectory::replace(const fs::path& final_folder) {
  throw_if_stop_requested();  // a run asked to stop keeps nothing, however far it got
  seal();
  std::error_code ec;
  const bool earlier = fs::exists(fs::symlink_status(final_folder, ec));
  // Exchanged, the temporary name holds the earlier output, removed below.
  if (earlier && ::renameat2(AT_FDCWD, path_.c_str(), AT_FDCWD, final_folder.c_str(), RENAME_EXCHANGE) != 0) {
    // No exchange on this file system: move the earlier folder aside first.
    const fs::path aside = path_.string() + "-old";
    fs::rename(final_folder, aside, ec);
    if (!ec) fs::rename(path_, final_folder, ec);
    if (ec) {
      std::error_code ignored;
      fs::rename(aside, final_folder, ignored);
      throw OutputError("cannot move the finished output to '" + final_folder.string() + "': " + ec.message());
    }
    fs::remove_all(aside, ec);
  } else if (!earlier) {
    fs::rename(path_, final_folder, ec);
    if (ec) throw OutputError("cannot move the finished output to '" + final_folder.string() + "': " + ec.message());
  }
  fs::remove_all(path_, ec);  // the earlier output, when exchanged
  done_ = true;
  parents_.keep();
}

void TemporaryDirectory::move_files_into_location() {
  throw_if_stop_requested();  // before the first move: the set is replaced whole, or not at all
  std::error_code ec;
  fs::remove(path_ / kClaimName, ec);  // the folder's, not an output
  for (const auto& entry : fs::directory_iterator(path_, ec)) {
    const fs::path to = location_ / entry.path().filename();
    fs::rename(entry.path(), to, ec);
    if (ec) throw OutputError("cannot move the finished output to '" + to.string() + "': " + ec.message());
  }
  fs::remove(path_, ec);
  done_ = true;
  parents_.keep();
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
