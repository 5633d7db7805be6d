// Creates the directory an output needs (with missing parents), and removes it again if the run fails.
#include "render/output/created_directory.hpp"

#include <system_error>

#include "render/output/output_error.hpp"
#include "render/output/temporary_file.hpp"

namespace fs = std::filesystem;

namespace vibra::render {

namespace {
/// "frames/" names the directory "frames".
fs::path without_trailing_separator(fs::path directory) {
  if (!directory.has_filename() && directory.has_parent_path()) directory = directory.parent_path();
  return directory.empty() ? fs::path(".") : directory;
}

/// The missing directories of `target`, innermost first, and sets `existing`
/// to the first ancestor that exists.
std::vector<fs::path> missing_directories(const fs::path& target, fs::path& existing) {
  std::vector<fs::path> missing;
  std::error_code ec;
  existing = target;
  while (!existing.empty() && !fs::exists(fs::status(existing, ec))) {
    missing.push_back(existing);
    existing = existing.parent_path();
  }
  if (existing.empty()) existing = ".";
  return missing;
}
}  // namespace

void require_creatable_directory(const fs::path& directory) {
  fs::path existing;
  missing_directories(without_trailing_separator(directory), existing);
  require_writable_directory(existing);
}

CreatedDirectory::CreatedDirectory(const fs::path& directory) {
  const fs::path target = without_trailing_separator(directory);
  fs::path existing;
  const std::vector<fs::path> missing = missing_directories(target, existing);
  require_writable_directory(existing);
  std::error_code ec;
  try {
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
      if (!fs::create_directory(*it, ec) && ec)
        throw OutputError("cannot create directory '" + it->string() + "': " + ec.message() +
                          ": choose another output path");
      created_.push_back(*it);
    }
  } catch (...) {
    remove_created();
    throw;
  }
}

CreatedDirectory::CreatedDirectory(CreatedDirectory&& other) noexcept : created_(std::move(other.created_)) {
  other.created_.clear();
}

CreatedDirectory& CreatedDirectory::operator=(CreatedDirectory&& other) noexcept {
  if (this != &other) {
    remove_created();
    created_ = std::move(other.created_);
    other.created_.clear();
  }
  return *this;
}

CreatedDirectory::~CreatedDirectory() { remove_created(); }

void CreatedDirectory::remove_created() noexcept {
  std::error_code ec;
  for (auto it = created_.rbegin(); it != created_.rend(); ++it) fs::remove(*it, ec);  // only while empty
  created_.clear();
}

}  // namespace vibra::render
