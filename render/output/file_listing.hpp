// A listing of files vibra wrote (name, size, FNV-1a hash): the form of its manifests and frame ledgers.
#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace vibra::render {

/// What vibra knows of a file it wrote: enough to tell it from anything else.
struct Fingerprint {
  std::uintmax_t size = 0;
  std::uint64_t hash = 0xcbf29ce484222325ull;  ///< FNV-1a 64 of the bytes
  bool operator==(const Fingerprint&) const = default;
  /// Extends the fingerprint by `n` more bytes.
  void add(const void* bytes, std::size_t n);
};

/// The fingerprint of `n` bytes, as written to a file.
Fingerprint fingerprint_of(const void* bytes, std::size_t n);

/// The fingerprint of the plain file at `path` (not followed if a link);
/// none when it cannot be read. Polls the stop flag every 16 MiB.
std::optional<Fingerprint> fingerprint_file(const std::filesystem::path& path);

/// File names (in one folder) and their fingerprints.
using FileListing = std::map<std::string, Fingerprint>;

/// More entries than this is no listing of vibra's (a page's frames player
/// holds one file per frame: 1e6 frames at most).
inline constexpr std::size_t kMostListedFiles = 2'000'000;

/// The listing in `file`, or none when it is not one vibra wrote: another
/// user's, unreadable, not a plain file, too long, or not in the form.
/// Polls the stop flag.
std::optional<FileListing> read_file_listing(const std::filesystem::path& file);

/// Writes `listing` to `file` under a temporary name, then renames it into
/// place; `what` names the listing in the error. Throws OutputError.
void write_file_listing(const std::filesystem::path& file, const FileListing& listing, const std::string& what);

}  // namespace vibra::render
