// OutputError: a failure writing an output (unwritable path, disk full, missing encoder).
#pragma once
#include <stdexcept>
#include <string>

namespace vibra::render {
/// A failure writing an output (unwritable path, disk full, missing encoder).
/// The message is one line that names the problem and the fix; the CLI exits 2.
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
}  // namespace vibra::render
