// The chapter site's index page: every figure and exercise in order, its commands, outputs and the book's numbers.
#pragma once
#include <string>
#include <vector>

#include "cli/chapter/chapter_book_values.hpp"
#include "cli/chapter/chapter_items.hpp"

namespace vibra::cli {

/// A book number beside vibra's: `vibra` is the cell as printed, "" when the output lacks it.
struct NumberResult {
  const BookNumber* number;
  std::string vibra;
  bool agrees;
};

/// What one command left in the site: the file it wrote (-o) and its standard output.
struct CommandResult {
  std::vector<std::string> args;
  std::string output;     ///< the file named by -o, "" for none
  std::string text_file;  ///< its standard output's file, "" when it printed nothing
  std::string text;       ///< that output, as kept
};

struct ItemResult {
  const ChapterItem* item;
  std::vector<CommandResult> commands;
  std::vector<NumberResult> numbers;
};

/// The index page: static HTML with relative links only (opens from file://, needs no network).
/// `only` is --only's value ("" for the whole chapter).
std::string chapter_index_html(const std::vector<ItemResult>& items, const std::string& only);

}  // namespace vibra::cli
