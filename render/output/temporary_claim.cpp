// Proof that a temporary left in a folder is vibra's own, so that a later run may remove it.
#include "render/output/temporary_claim.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

#include "core/stop_flag.hpp"
#include "render/output/output_error.hpp"
#include "render/output/ownership_manifest.hpp"

namespace fs = std::filesystem;

namespace vibra::render {

namespace {
constexpr int kDeepest = 3;  ///< temporaries nest: a page's folder holds its frames' folder

/// The claim's text for a folder with this status.
std::string claim_text(const struct stat& folder) {
  return "vibra temporary folder " + std::to_string(folder.st_dev) + " " + std::to_string(folder.st_ino) + "\n";
}

bool plain_file_of_user(const fs::path& file) {
  struct stat st {};
  return ::lstat(file.c_str(), &st) == 0 && S_ISREG(st.st_mode) && st.st_uid == ::geteuid() && st.st_nlink == 1;
}

bool claimed_folder(const fs::path& folder, int depth) {
  struct stat st {};
  if (depth > kDeepest || !why_unreadable(folder).empty() || ::lstat(folder.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    return false;
  if (why_not_vibras(folder).empty()) return true;  // finished output moved aside, its manifest intact
  const fs::path claim = folder / kClaimName;
  if (!plain_file_of_user(claim) || !why_unreadable(claim).empty()) return false;
  std::ifstream in(claim, std::ios::binary);
  std::string text(std::istreambuf_iterator<char>(in), {});
  if (text != claim_text(st)) return false;
  std::error_code ec;
  long long seen = 0;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    if ((++seen & 0xff) == 0) throw_if_stop_requested();
    const bool ours = plain_file_of_user(entry.path()) || claimed_folder(entry.path(), depth + 1);
    if (!ours) return false;
  }
  return !ec;
}
}  // namespace

void write_claim(const fs::path& folder) {
  struct stat st {};
  const fs::path claim = folder / kClaimName;
  std::FILE* out = ::lstat(folder.c_str(), &st) == 0 ? std::fopen(claim.c_str(), "wbx") : nullptr;
  const std::string text = out ? claim_text(st) : "";
  const bool ok = out && std::fwrite(text.data(), 1, text.size(), out) == text.size();
  if (!out || std::fclose(out) != 0 || !ok)
    throw OutputError("cannot write in the folder '" + folder.string() + "' vibra made: choose another output path");
}

bool provably_vibras_temporary(const fs::path& temporary) {
  std::error_code ec;
  return fs::is_directory(fs::symlink_status(temporary, ec)) ? claimed_folder(temporary, 0)
                                                             : plain_file_of_user(temporary);
}

}  // namespace vibra::render
