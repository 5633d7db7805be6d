// The rules of shown_path.hpp: what of a path a record of the run may show.
#include "core/input/shown_path.hpp"

#include <filesystem>

namespace vibra {

namespace fs = std::filesystem;

namespace {
/// Paths that name no one's folders: shown as given.
constexpr const char* kShownAsGiven[] = {"/dev/", "/proc/"};

/// The path with its folder's links resolved, as the working directory's are.
fs::path resolved(const fs::path& path) {
  std::error_code ec;
  const fs::path folder = fs::weakly_canonical(path.parent_path(), ec);
  return ec ? path.lexically_normal() : folder / path.filename();
}
}  // namespace

std::string shown_path(const std::string& path) {
  if (path.empty() || path.front() != '/') return path;
  for (const char* prefix : kShownAsGiven)
    if (path.starts_with(prefix)) return path;
  std::error_code ec;
  const fs::path here = fs::current_path(ec);
  const fs::path target = resolved(path);
  const auto first_folder = [](const fs::path& p) { return std::next(p.begin()) == p.end() ? fs::path() : *std::next(p.begin()); };
  const fs::path relative = ec || first_folder(here) != first_folder(target) ? fs::path() : target.lexically_relative(here);
  return relative.empty() ? target.filename().string() : relative.string();
}

std::string shown_argument(const std::string& argument) {
  if (argument.starts_with("/")) return shown_path(argument);
  const std::size_t eq = argument.find('=');
  if (eq == std::string::npos || argument.compare(eq + 1, 1, "/") != 0) return argument;
  return argument.substr(0, eq + 1) + shown_path(argument.substr(eq + 1));
}

}  // namespace vibra
