// A listing of files vibra wrote (name, size, FNV-1a hash): reading, writing, and fingerprinting files.
#include "render/output/file_listing.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/stop_flag.hpp"
#include "render/output/output_error.hpp"
#include "render/output/ownership_manifest.hpp"
#include "render/output/temporary_file.hpp"

namespace fs = std::filesystem;

namespace vibra::render {

namespace {
constexpr const char* kHeader = "vibra manifest 1";
/// A listing of kMostListedFiles entries takes about 100 MiB; a longer file is none of vibra's.
constexpr std::uintmax_t kLongestListing = 256ull << 20;

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

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;  // escaped() writes upper case only
}

/// The name `escaped` wrote, or none when the text is not in its form.
std::optional<std::string> unescaped(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '%') {
      out += text[i];
      continue;
    }
    const int high = i + 2 < text.size() ? hex_digit(text[i + 1]) : -1;
    const int low = high < 0 ? -1 : hex_digit(text[i + 2]);
    if (low < 0) return std::nullopt;
    out += char(high * 16 + low);
    i += 2;
  }
  return out;
}
}  // namespace

void Fingerprint::add(const void* bytes, std::size_t n) {
  const auto* p = static_cast<const unsigned char*>(bytes);
  std::uint64_t h = hash;
  for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 0x100000001b3ull;
  hash = h;
  size += n;
}

Fingerprint fingerprint_of(const void* bytes, std::size_t n) {
  Fingerprint f;
  f.add(bytes, n);
  return f;
}

std::optional<Fingerprint> fingerprint_file(const fs::path& path) {
  struct Descriptor {
    int fd;
    ~Descriptor() {
      if (fd >= 0) ::close(fd);
    }
  } file{::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC)};
  if (file.fd < 0) return std::nullopt;
  Fingerprint f;
  static thread_local char chunk[1 << 16];
  for (long long chunks = 0;; ++chunks) {
    if ((chunks & 0xff) == 0xff) throw_if_stop_requested();  // 16 MiB between looks
    const ssize_t got = ::read(file.fd, chunk, sizeof chunk);
    if (got == 0) break;
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) return std::nullopt;
    f.add(chunk, static_cast<std::size_t>(got));
  }
  return f;
}

std::optional<FileListing> read_file_listing(const fs::path& file) {
  std::error_code ec;
  if (!why_unreadable(file).empty() || !fs::is_regular_file(fs::symlink_status(file, ec)) ||
      fs::file_size(file, ec) > kLongestListing)
    return std::nullopt;
  std::ifstream in(file, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line != kHeader) return std::nullopt;
  FileListing listing;
  for (std::size_t lines = 0; std::getline(in, line); ++lines) {  // lines, not names: a name may repeat
    if (lines >= kMostListedFiles) return std::nullopt;
    if ((lines & 0xffff) == 0xffff) throw_if_stop_requested();
    std::istringstream fields(line);
    Fingerprint f;
    std::string text;
    if (!(fields >> f.size >> std::hex >> f.hash) || fields.get() != ' ' || !std::getline(fields, text)) return std::nullopt;
    const std::optional<std::string> name = unescaped(text);
    if (!name) return std::nullopt;
    listing[*name] = f;
  }
  return in.eof() ? std::optional(listing) : std::nullopt;
}

void write_file_listing(const fs::path& file, const FileListing& listing, const std::string& what) {
  std::string text = std::string(kHeader) + "\n";
  long long count = 0;
  for (const auto& [name, f] : listing) {
    if ((++count & 0xffff) == 0) throw_if_stop_requested();
    char fields[48];
    std::snprintf(fields, sizeof fields, "%ju %016llx ", f.size, static_cast<unsigned long long>(f.hash));
    text += fields + escaped(name) + "\n";
  }
  TemporaryFile temporary(file);
  std::FILE* out = std::fopen(temporary.path().c_str(), "wb");
  const bool ok = out && std::fwrite(text.data(), 1, text.size(), out) == text.size();
  if (!out || std::fclose(out) != 0 || !ok)
    throw OutputError("writing " + what + " in '" + file.parent_path().string() + "' failed (disk full?)");
  temporary.commit();
}

}  // namespace vibra::render
