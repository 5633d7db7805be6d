// Proof that vibra wrote a folder: a manifest of its files (names, sizes, hashes) that vibra writes last.
#include "render/output/ownership_manifest.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "core/quoted_value.hpp"
#include "core/stop_flag.hpp"
#include "render/output/output_error.hpp"
#include "render/output/temporary_file.hpp"

namespace fs = std::filesystem;

namespace vibra::render {

namespace {
constexpr const char* kHeader = "vibra manifest 1";
/// More entries than this in a folder vibra wrote is not a folder vibra wrote
/// (a page's frames player holds one file per frame: 1e6 frames at most).
constexpr std::size_t kMostEntries = 2'000'000;
/// A manifest of that many entries takes about 100 MiB; a longer file is none of vibra's.
constexpr std::uintmax_t kLongestManifest = 256ull << 20;

/// What vibra knows of a file it wrote.
struct Fingerprint {
  std::uintmax_t size = 0;
  std::uint64_t hash = 0;
  bool operator==(const Fingerprint&) const = default;
};

/// The size and FNV-1a hash of the plain file at `path` (not followed if a
/// link); none when it cannot be read. Polls the stop flag every 16 MiB.
std::optional<Fingerprint> fingerprint(const fs::path& path) {
  struct Descriptor {
    int fd;
    ~Descriptor() {
      if (fd >= 0) ::close(fd);
    }
  } file{::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC)};
  if (file.fd < 0) return std::nullopt;
  Fingerprint f{0, 0xcbf29ce484222325ull};
  static thread_local char chunk[1 << 16];
  for (long long chunks = 0;; ++chunks) {
    if ((chunks & 0xff) == 0xff) throw_if_stop_requested();  // 16 MiB between looks
    const ssize_t got = ::read(file.fd, chunk, sizeof chunk);
    if (got == 0) break;
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) return std::nullopt;
    for (ssize_t i = 0; i < got; ++i) f.hash = (f.hash ^ static_cast<unsigned char>(chunk[i])) * 0x100000001b3ull;
    f.size += static_cast<std::uintmax_t>(got);
  }
  return f;
}

/// A name on one line: control bytes and '%' as %XX.
std::string escaped(const std::string& name) {
  std::string out;
  for (unsigned char c : name) {
    if (c >= 0x20 && c != '%' && c != 0x7f) out += char(c);
    else {
      char code[4];
      std::snprintf(code, sizeof code, "%%%02X", c);
      out += code;
    }
  }
  return out;
}

using Manifest = std::map<std::string, Fingerprint>;  // by escaped name

std::optional<Manifest> read_manifest(const fs::path& file) {
  std::error_code ec;
  if (!why_unreadable(file).empty() || !fs::is_regular_file(fs::symlink_status(file, ec)) ||
      fs::file_size(file, ec) > kLongestManifest)
    return std::nullopt;
  std::ifstream in(file, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line != kHeader) return std::nullopt;
  Manifest m;
  for (std::size_t lines = 0; std::getline(in, line) && lines < kMostEntries; ++lines) {  // lines, not names: a name may repeat
    if ((lines & 0xffff) == 0xffff) throw_if_stop_requested();
    std::istringstream fields(line);
    Fingerprint f;
    std::string name;
    if (!(fields >> f.size >> std::hex >> f.hash) || fields.get() != ' ' || !std::getline(fields, name)) return std::nullopt;
    m[name] = f;
  }
  return in.eof() ? std::optional(m) : std::nullopt;
}

/// Why the entry `name` of a folder with manifest `m` is not a file vibra wrote there, or "".
std::string why_not_listed(const fs::directory_entry& entry, const Manifest& m) {
  const std::string name = quoted_value(entry.path().filename().string(), 40);
  if (!why_unreadable(entry.path()).empty() || !entry.is_regular_file() || entry.is_symlink())
    return "holds '" + name + "', which is not a file vibra wrote";
  const auto listed = m.find(escaped(entry.path().filename().string()));
  if (listed == m.end()) return "holds '" + name + "', which vibra did not write (it is not in vibra's manifest)";
  if (fingerprint(entry.path()) != listed->second) return "holds '" + name + "', which changed since vibra wrote it";
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
  const std::optional<Manifest> manifest = read_manifest(folder / kManifestName);
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
  std::string text = std::string(kHeader) + "\n";
  std::error_code ec;
  long long count = 0;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    if ((++count & 0xff) == 0) throw_if_stop_requested();
    const std::string name = entry.path().filename().string();
    if (name == kManifestName) continue;
    const std::optional<Fingerprint> f = fingerprint(entry.path());
    if (!f) throw OutputError("cannot read back '" + entry.path().string() + "' to list it: " + std::strerror(errno));
    char fields[48];
    std::snprintf(fields, sizeof fields, "%ju %016llx ", f->size, static_cast<unsigned long long>(f->hash));
    text += fields + escaped(name) + "\n";
  }
  if (ec) throw OutputError("cannot list '" + folder.string() + "': " + ec.message());
  TemporaryFile file(folder / kManifestName);
  std::FILE* out = std::fopen(file.path().c_str(), "wb");
  const bool ok = out && std::fwrite(text.data(), 1, text.size(), out) == text.size();
  if (!out || std::fclose(out) != 0 || !ok)
    throw OutputError("writing the list of what vibra wrote in '" + folder.string() + "' failed (disk full?)");
  file.commit();
}

}  // namespace vibra::render
