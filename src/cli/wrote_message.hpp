#pragma once
#include <cstdio>
#include <string>

namespace vibra::cli {

/// The closing line every command that writes files prints on stderr, as
/// `vibra render` does: "vibra: wrote WHAT". Silent with --quiet.
inline void say_wrote(bool quiet, const std::string& what) {
  if (!quiet) std::fprintf(stderr, "vibra: wrote %s\n", what.c_str());
}

}  // namespace vibra::cli
