// Puts a run's finished outputs in place all together, or none of them.
#include "render/output/place_together.hpp"

#include <fcntl.h>
#include <stdio.h>

#include <cerrno>
#include <system_error>

#include "render/output/output_error.hpp"
#include "render/output/stop_signal.hpp"

namespace fs = std::filesystem;

namespace vibra::render {

namespace {
/// How one output was placed, so that it can be undone.
enum class Placed { renamed, exchanged, moved_aside };

/// Moves `p.temporary` to `p.final`; returns how, or throws std::system_error.
Placed place_one(const Placement& p) {
  std::error_code ec;
  const fs::file_status earlier = fs::symlink_status(p.final, ec);
  // A folder where a file goes, or a file where a folder goes, is not output to replace.
  if (fs::exists(earlier) && fs::is_directory(earlier) != fs::is_directory(fs::symlink_status(p.temporary, ec)))
    throw std::system_error(std::make_error_code(fs::is_directory(earlier) ? std::errc::is_a_directory
                                                                             : std::errc::not_a_directory));
  if (!fs::exists(earlier)) {
    fs::rename(p.temporary, p.final);
    return Placed::renamed;
  }
  if (::renameat2(AT_FDCWD, p.temporary.c_str(), AT_FDCWD, p.final.c_str(), RENAME_EXCHANGE) == 0)
    return Placed::exchanged;
  if (errno != EINVAL && errno != ENOSYS) throw std::system_error(errno, std::generic_category());
  // No exchange on this file system: the earlier output waits beside the temporary.
  const fs::path aside = p.temporary.string() + "-old";
  fs::rename(p.final, aside);
  try {
    fs::rename(p.temporary, p.final);
  } catch (...) {
    fs::rename(aside, p.final, ec);
    throw;
  }
  fs::rename(aside, p.temporary, ec);  // where its owner removes it, as after an exchange
  return Placed::moved_aside;
}

/// Puts back the earlier output of a placed `p` (best effort: it runs while failing).
void undo(const Placement& p, Placed how) noexcept {
  std::error_code ec;
  if (how == Placed::renamed) {
    fs::rename(p.final, p.temporary, ec);
  } else if (how == Placed::exchanged) {
    ::renameat2(AT_FDCWD, p.temporary.c_str(), AT_FDCWD, p.final.c_str(), RENAME_EXCHANGE);
  } else {  // the new output at the final path, the earlier at the temporary's: swapped by hand
    const fs::path aside = p.temporary.string() + "-new";
    fs::rename(p.final, aside, ec);
    fs::rename(p.temporary, p.final, ec);
    fs::rename(aside, p.temporary, ec);
  }
}
}  // namespace

void place_together(const std::vector<Placement>& outputs) {
  throw_if_stop_requested();  // before the first: a run asked to stop places nothing
  std::vector<Placed> done;
  for (const Placement& p : outputs) {
    try {
      done.push_back(place_one(p));
    } catch (const std::system_error& e) {
      for (std::size_t i = done.size(); i-- > 0;) undo(outputs[i], done[i]);
      throw OutputError("cannot move the finished output to '" + p.final.string() + "': " +
                        e.code().message() + ": nothing was replaced; move what is there away and run again");
    }
  }
}

}  // namespace vibra::render
