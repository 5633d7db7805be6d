// Proof that vibra wrote a folder: a manifest of its files (names, sizes, hashes) that vibra writes last.
#include "render/output/ownership_manifest.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>

#include "core/input/quoted_value.hpp"
#include "core/stop_flag.hpp"
#include "render/output/file_listing.hpp"
#include "render/output/output_error.hpp"

namespace fs = std::filesystem;

namespace vibra::render {

namespace {
/// Why the entry of a folder with listing `listed` is not a file vibra wrote there, or "".
std::string why_not_listed(const fs::directory_entry& entry, const FileListing& listed) {
  const std::string name = quoted_value(entry.path().filename().string(), 40);
  if (!why_unreadable(entry.path()).empty() || !entry.is_regular_file() || entry.is_symlink())
    return "holds '" + name + "', which is not a file vibra wrote";
  const auto found = listed.find(entry.path().filename().string());
  if (found == listed.end()) return "holds '" + name + "', which vibra did not write (it is not in vibra's manifest)";
  if (fingerprint_file(entry.path()) != found->second) return "holds '" + name + "', which changed since vibra wrote it";
  return "";
}
}  // namespace

std::string why_unreadable(const fs::path& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) return std::string("cannot be examined: ") + std::strerror(errno);
  if (st.st_uid != ::geteuid()) return "belongs to another user (uid " + std::to_string(st.st_uid) + ")";
  const mode_t needed = S_ISDIR(st.st_mode) ? (S_IRUSR | S_IWUSR | S_IXUSR) : S_IRUSR;
  if ((st.st_mode & needed) != needed) {
    char mode[8];
    std::snprintf(mode, sizeof mode, "%03o", unsigned(st.st_mode & 0777));
    return std::string("has mode ") + mode + ", which does not let its owner " +
           (S_ISDIR(st.st_mode) ? "read and enter" : "read") + " it";
  }
  return "";
}

std::string why_not_vibras(const fs::path& folder) {
  if (std::string why = why_unreadable(folder); !why.empty()) return why;
  if (!fs::is_directory(fs::symlink_status(folder))) return "is not a folder";
  const std::optional<FileListing> manifest = read_file_listing(folder / kManifestName);
  if (!manifest) return std::string("holds no manifest of what vibra wrote there (") + kManifestName + ")";
  std::error_code ec;
  std::size_t seen = 0;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    if ((++seen & 0xff) == 0) throw_if_stop_requested();
    if (seen > manifest->size() + 1) return "holds more files than vibra wrote there";
    if (entry.path().filename() == kManifestName) continue;
    if (std::string why = why_not_listed(entry, *manifest); !why.empty()) return why;
  }
  return ec ? "cannot be listed: " + ec.message() : "";
}

void write_manifest(const fs::path& folder) {
  FileListing listing;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    if ((listing.size() & 0xff) == 0xff) throw_if_stop_requested();
    const std::string name = entry.path().filename().string();
    if (name == kManifestName) continue;
    const std::optional<Fingerprint> f = fingerprint_file(entry.path());
    if (!f) throw OutputError("cannot read back '" + entry.path().string() + "' to list it: " + std::strerror(errno));
    listing[name] = *f;
  }
  if (ec) throw OutputError("cannot list '" + folder.string() + "': " + ec.message());
  write_file_listing(folder / kManifestName, listing, "the list of what vibra wrote");
}

}  // namespace vibra::render
