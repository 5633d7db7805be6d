// The files a run reads, noted as they are opened, so no output of the run overwrites one.
#include "core/input/input_files.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <mutex>
#include <sstream>
#include <vector>

#include "core/error.hpp"
#include "core/input/quoted_value.hpp"

namespace vibra {

namespace {
struct Noted {
  InputFile file;
  dev_t device;
  ino_t inode;
};

std::mutex mutex;
std::vector<Noted> noted;  // guarded by mutex
}  // namespace

void note_input_file(const std::filesystem::path& path, std::string role) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) return;
  std::lock_guard lock(mutex);
  noted.push_back({{path, std::move(role)}, status.st_dev, status.st_ino});
}

std::vector<InputFile> input_files() {
  std::lock_guard lock(mutex);
  std::vector<InputFile> files;
  for (const Noted& n : noted) files.push_back(n.file);
  return files;
}

std::string read_input_file(const std::string& path, const std::string& what, std::string role,
                            std::size_t most_bytes) {
  const auto refuse = [&](int error) {
    throw UsageError("cannot read " + what + " '" + quoted_value(path, 80) + "': " + std::strerror(error) +
                     (error == EACCES ? ": give vibra read permission (chmod a+r) or copy it" : ""));
  };
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) refuse(errno ? errno : EACCES);
  note_input_file(path, std::move(role));
  std::string text;
  char chunk[65536];
  while (in && text.size() <= most_bytes) {  // bounded by most_bytes: a huge file is not read whole
    const std::size_t left = most_bytes - text.size();  // one byte more than allowed tells a longer file
    in.read(chunk, std::streamsize(left < sizeof chunk ? left + 1 : sizeof chunk));
    text.append(chunk, std::size_t(in.gcount()));
  }
  if (in.bad()) refuse(errno ? errno : EIO);
  if (text.size() > most_bytes)
    throw UsageError(what + " '" + quoted_value(path, 80) + "' is longer than " + std::to_string(most_bytes >> 10) +
                     " KiB, the most vibra reads of it: is it the right file? Split it, or shorten what it holds");
  return text;
}

std::optional<InputFile> input_at(const std::filesystem::path& output) {
  struct stat status {};
  if (::stat(output.c_str(), &status) != 0) return std::nullopt;  // not there: read by no one
  std::lock_guard lock(mutex);
  for (const Noted& n : noted)
    if (n.device == status.st_dev && n.inode == status.st_ino) return n.file;
  return std::nullopt;
}

void forget_input_files() {
  std::lock_guard lock(mutex);
  noted.clear();
}

}  // namespace vibra
