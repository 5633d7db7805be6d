#include "render/temporary_file.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
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

TemporaryFile::TemporaryFile(fs::path final_path) : final_(std::move(final_path)) {
  if (final_.filename().empty())
    throw OutputError("output path '" + final_.string() + "' names a directory, not a file: add a file name");
  std::error_code ec;
  if (fs::is_directory(final_, ec))
    throw OutputError("output path '" + final_.string() + "' is a directory: give a file name");
  require_writable_directory(directory_of(final_));
  std::string name = ".";
  name += final_.filename().string();
  name += kTag;
  name += std::to_string(getpid());
  temp_ = directory_of(final_) / name;
}

TemporaryFile::~TemporaryFile() {
  if (!done_) discard();
}

void TemporaryFile::commit() {
  std::error_code ec;
  fs::rename(temp_, final_, ec);
  if (ec) {
    discard();
    throw OutputError("cannot move the finished output to '" + final_.string() + "': " + ec.message());
  }
  done_ = true;
}

void TemporaryFile::discard() noexcept {
  std::error_code ec;
  fs::remove(temp_, ec);
  done_ = true;
}

std::vector<fs::path> TemporaryFile::stale_in(const fs::path& dir) {
  std::vector<fs::path> stale;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    std::string name = entry.path().filename().string();
    auto at = name.rfind(kTag);
    if (name.empty() || name[0] != '.' || at == std::string::npos) continue;
    long pid = std::strtol(name.c_str() + at + std::strlen(kTag), nullptr, 10);
    bool alive = pid > 0 && (kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM);
    if (!alive) stale.push_back(entry.path());
  }
  return stale;
}

}  // namespace vibra::render
