// What the fuzz targets feed to vibra, shared by the libFuzzer executables (tests/fuzz/fuzz_*.cpp) and by the Catch test that replays the corpus and every regression input in the normal suite.
// Each entry accepts the errors vibra reports to users (UsageError,
// SolutionError); anything else escapes and is a finding.
#pragma once
#include <string_view>

namespace vibra::fuzz {

/// A scene file: TOML text, loaded, its model built and stepped a little.
void scene_file(std::string_view text);
/// A lecture storyboard: TOML text read as `vibra lecture` reads it (every
/// shot's keys, scene, pacing and notes), each scene shot's model built and
/// stepped a little, its frame clock made.
void storyboard(std::string_view text);
/// `--set` lines: the first byte picks a model, each further line is one
/// KEY=VALUE; then every value is read and the model stepped a little.
void set_assignments(std::string_view text);
/// An expression in u and t, compiled and evaluated; also as a constant.
void expression(std::string_view text);
/// A formula in the LaTeX subset, parsed, laid out and drawn on a small
/// picture; the same text as a note's rich text (words and $math$).
void formula(std::string_view text);
/// A command line, one argument per line (the first names the command), run
/// in this process as `vibra` runs it, with a tiny picture, files in a
/// scratch folder, output in memory and a stop after 1.5 s; exit code 0, 2
/// or 130, and an error must be one line (fuzz_command_line_input.cpp).
void command_line(std::string_view text);

}  // namespace vibra::fuzz
