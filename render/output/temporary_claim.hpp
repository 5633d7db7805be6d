// Proof that a temporary left in a folder is vibra's own, so that a later run may remove it.
#pragma once
#include <filesystem>

namespace vibra::render {

/// The claim a temporary folder holds from the moment vibra makes it.
inline constexpr const char* kClaimName = ".vibra-claim";

/// Puts a claim in the folder vibra has just made: the folder's own device
/// and inode, which no other folder has while it exists. Throws OutputError.
void write_claim(const std::filesystem::path& folder);

/// Whether a temporary named as vibra names them (`.NAME.vibra-tmp-HOST-PID`)
/// is provably vibra's own, so that it may be removed: a plain file of the
/// user running vibra with no other name (a killed run's partial file: its
/// bytes prove nothing), or a folder of that user, readable by its mode,
/// holding vibra's claim naming that very folder, or a manifest that
/// matches (ownership_manifest.hpp), and only such files and folders.
bool provably_vibras_temporary(const std::filesystem::path& temporary);

}  // namespace vibra::render
