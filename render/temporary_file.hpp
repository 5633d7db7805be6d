#pragma once
#include <filesystem>
#include <vector>

namespace vibra::render {

/// A file written under a temporary name beside its final path and renamed
/// into place only by commit(), so the final path never holds a partial file.
/// Temporary names look like `.NAME.vibra-tmp-HOST-PID` so a killed run's
/// leftovers are recognisable; the first TemporaryFile in a directory removes
/// (and reports on stderr) those of this host whose process is gone. Other
/// hosts' temporaries are left alone: on a shared disk they may be live. The destructor removes an
/// uncommitted temporary. An existing device or pipe (/dev/null, a FIFO) is
/// written directly: there is nothing to rename.
class TemporaryFile {
 public:
  /// Checks that the directory exists and is writable; throws OutputError otherwise.
  explicit TemporaryFile(std::filesystem::path final_path);
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile();

  const std::filesystem::path& path() const { return temp_; }
  const std::filesystem::path& final_path() const { return final_; }

  /// Renames the temporary to the final path; throws OutputError on failure.
  void commit();
  /// Removes the temporary (best effort, never throws).
  void discard() noexcept;

  /// Temporaries left in `dir` by killed runs (`.*.vibra-tmp-HOST-PID`, this host, PID gone).
  static std::vector<std::filesystem::path> stale_in(const std::filesystem::path& dir);

 private:
  std::filesystem::path final_;
  std::filesystem::path temp_;
  bool done_ = false;
  bool direct_ = false;
};

/// Throws OutputError unless `dir` is an existing, writable directory.
void require_writable_directory(const std::filesystem::path& dir);

}  // namespace vibra::render
