// The files a run reads, noted as they are opened, so no output of the run overwrites one.
#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vibra {

/// The files a run reads (a scene file, a road profile, the parts vibra
/// concat joins), noted as they are opened, so that no output of the same run
/// is written over one of them (render/output/output_path.hpp asks input_at).
struct InputFile {
  std::filesystem::path path;  ///< as the user named it
  std::string role;            ///< what it is, for messages: "the road profile (--set road)"
};

/// Notes that this run reads `path`. A path that cannot be found is ignored.
void note_input_file(const std::filesystem::path& path, std::string role);

/// The input that `output` is (the same file, also through links or another
/// spelling), if any.
std::optional<InputFile> input_at(const std::filesystem::path& output);

/// The whole of the input file at `path`, noted as an input with `role`.
/// `what` names it in the one-line error a file that cannot be opened or read
/// gives ("the scene file"): the system's reason, and for a permission the fix.
/// A file longer than `most_bytes` is refused after reading only that much
/// (one line naming the limit), so that a huge file costs no time or memory.
std::string read_input_file(const std::string& path, const std::string& what, std::string role,
                            std::size_t most_bytes = SIZE_MAX);

/// The most a text file of settings (a scene file, a storyboard) may hold: 1 MiB.
inline constexpr std::size_t kMostSettingsBytes = std::size_t(1) << 20;

/// Every input noted so far, in the order they were opened.
std::vector<InputFile> input_files();

/// Forgets every input: a process that runs several commands (the Python
/// module) starts each afresh.
void forget_input_files();

}  // namespace vibra
