// TemporaryFile and TemporaryDirectory: outputs written under temporary names and put in place only on success.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "render/output/created_directory.hpp"

namespace vibra::render {

/// A file written under a temporary name beside its final path and renamed
/// into place only by commit(), so the final path never holds a partial file.
/// The final path goes through resolve_output_file (render/output/output_path.hpp):
/// a symbolic link's target gets the file (the temporary goes beside the
/// target, the link stays); a folder, pipe or device, or a file this run
/// reads, is refused. Missing parent folders are made, and removed again
/// unless the file is committed.
/// Temporary names look like `.NAME.vibra-tmp-HOST-PID` so a killed run's
/// leftovers are recognisable; the first TemporaryFile in a directory removes
/// (and reports on stderr) those of this host whose process is gone and that
/// are provably vibra's own (temporary_claim.hpp): a name alone is no proof. Other
/// hosts' temporaries are left alone: on a shared disk they may be live. The
/// destructor removes an uncommitted temporary.
class TemporaryFile {
 public:
  /// Throws OutputError when the path is refused or its folder cannot be made.
  explicit TemporaryFile(const std::filesystem::path& final_path);
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile();

  const std::filesystem::path& path() const { return temp_; }
  /// Where commit() puts the file: the path given, or the target of the link it names.
  const std::filesystem::path& final_path() const { return final_; }

  /// Renames the temporary to the final path; throws OutputError on failure.
  void commit();
  /// Removes the temporary (best effort, never throws).
  void discard() noexcept;

  /// Temporaries (files and folders) left in `dir` by killed runs (`.*.vibra-tmp-HOST-PID`, this host, PID gone).
  static std::vector<std::filesystem::path> stale_in(const std::filesystem::path& dir);

 private:
  std::filesystem::path final_;
  CreatedDirectory parents_;  ///< before temp_: removed after it
  std::filesystem::path temp_;
  bool done_ = false;
};

/// A folder built under a temporary name, `.NAME.vibra-tmp-HOST-PID` in
/// `location`, that takes the place of earlier output only when complete:
/// a PNG sequence's frames (moved into their folder one by one, over the
/// earlier run's) or a page's companions (the whole folder swapped in). Until
/// then earlier output stays as it was, byte for byte. The destructor removes
/// an uncommitted folder with all it holds, and the parents it made.
class TemporaryDirectory {
 public:
  /// Makes the folder (and `location` with its missing parents); throws OutputError.
  TemporaryDirectory(const std::filesystem::path& location, const std::string& name);
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  ~TemporaryDirectory();

  const std::filesystem::path& path() const { return path_; }
  /// Lists what the folder holds in its manifest, vibra's proof that it
  /// wrote them (ownership_manifest.hpp), in place of the claim it had while
  /// being filled (temporary_claim.hpp). Throws OutputError.
  void seal();
  /// Seals the folder and puts it in place of `final_folder`, replacing what is there (an
  /// atomic exchange where the file system has one), and removes the old.
  void replace(const std::filesystem::path& final_folder);
  /// Moves each file into `location`, over files of the same name, then
  /// removes the folder.
  void move_files_into_location();

 private:
  CreatedDirectory parents_;
  std::filesystem::path location_, path_;
  bool done_ = false;
};

/// `message` with each quoted path of a temporary ('...vibra-tmp-...')
/// replaced by `output`, the name the user gave: a failure while an output
/// is made (a full disk) names what the user asked for, not vibra's inside.
std::string said_of_output(std::string message, const std::string& output);

/// Throws OutputError unless `dir` is an existing, writable directory.
void require_writable_directory(const std::filesystem::path& dir);

}  // namespace vibra::render
