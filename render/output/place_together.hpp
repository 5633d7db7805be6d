// Puts a run's finished outputs in place all together, or none of them.
#pragma once
#include <filesystem>
#include <vector>

namespace vibra::render {

/// A finished output waiting under a temporary name (a file or a folder) and
/// the path it takes; both on one file system (the temporary beside it).
struct Placement {
  std::filesystem::path temporary, final;
};

/// Renames every temporary to its final path, in order, each over the earlier
/// output there (exchanged: the temporary name then holds the earlier output,
/// which its owner removes). When one cannot be placed, those placed before it
/// are put back as they were, byte for byte, and OutputError names the one;
/// the temporaries then still hold the new outputs, for their owners to remove.
void place_together(const std::vector<Placement>&);

}  // namespace vibra::render
