// The closing line "vibra: wrote WHAT" every command that writes files prints on stderr.
#pragma once
#include <cstdio>
#include <string>

#include "core/input/quoted_value.hpp"

namespace vibra::cli {

/// The closing line every command that writes files prints on stderr, as
/// `vibra render` does: "vibra: wrote WHAT". Silent with --quiet. One line
/// even for a file name with a newline in it (escaped, never cut).
inline void say_wrote(bool quiet, const std::string& what) {
  if (!quiet) std::fprintf(stderr, "vibra: wrote %s\n", one_line_message(what, what.size() * 4 + 16).c_str());
}

}  // namespace vibra::cli
