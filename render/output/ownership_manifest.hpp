// Proof that vibra wrote a folder: a manifest of its files (names, sizes, hashes) that vibra writes last.
#pragma once
#include <filesystem>
#include <string>

namespace vibra::render {

/// The manifest's name inside the folder it describes (a page's PAGE_files/).
inline constexpr const char* kManifestName = ".vibra-manifest";

/// Lists every file now in `folder` (its name, size and FNV-1a hash) in
/// `folder/.vibra-manifest`, written last and checked. Throws OutputError.
void write_manifest(const std::filesystem::path& folder);

/// Why `folder` is not provably vibra's own, or "" when it is: it is a folder
/// of the user running vibra whose mode bits let that user read it, holding
/// a manifest and nothing else than the plain files of that user the
/// manifest lists, each of the size and hash listed. Polls the stop flag.
std::string why_not_vibras(const std::filesystem::path& folder);

/// Why the mode bits and owner of `path` (not followed if a link) keep vibra
/// from proving anything in it, or "": another user's, or a mode that does
/// not let its owner read it (and enter it, for a folder). Root's power to
/// read anything does not count: such a folder is never moved.
std::string why_unreadable(const std::filesystem::path& path);

}  // namespace vibra::render
