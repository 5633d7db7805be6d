// Creates the directory an output needs (with missing parents), and removes it again if the run fails.
#pragma once
#include <filesystem>
#include <vector>

namespace vibra::render {

/// A directory an output needs, created (with its missing parents) if it does
/// not exist. A frame pattern or a frames directory is the product, so its
/// directory is made rather than refused; but an unfinished run leaves
/// nothing, so the destructor removes the directories this object created,
/// deepest first and only while empty, unless keep() was called.
class CreatedDirectory {
 public:
  /// Throws OutputError when a file stands where a directory is needed, or
  /// the directory cannot be created (naming the existing parent to check).
  explicit CreatedDirectory(const std::filesystem::path& directory);
  CreatedDirectory(const CreatedDirectory&) = delete;
  CreatedDirectory& operator=(const CreatedDirectory&) = delete;
  CreatedDirectory(CreatedDirectory&&) noexcept;
  CreatedDirectory& operator=(CreatedDirectory&&) noexcept;
  ~CreatedDirectory();

  /// The output is complete: the directories stay.
  void keep() { created_.clear(); }
  /// The directories this object made, outermost first.
  const std::vector<std::filesystem::path>& created() const { return created_; }

 private:
  void remove_created() noexcept;
  std::vector<std::filesystem::path> created_;
};

/// Throws OutputError unless `directory` is a writable directory or can be
/// created: its nearest existing ancestor is a writable directory (a file in
/// the way is named).
void require_creatable_directory(const std::filesystem::path& directory);

}  // namespace vibra::render
