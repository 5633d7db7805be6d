// The chapter's figures and exercises as one table: what `vibra chapter` runs and shows.
#pragma once
#include <string>
#include <vector>

namespace vibra::cli {

enum class ItemKind { figure, exercise };

/// One figure (1.1-1.22) or exercise (1.1-1.28) of chapter 1 of Linge &
/// Langtangen, with the vibra commands that answer it (docs/exercises.md
/// lists the same commands; tests/cli/chapter_test.cpp checks that they agree).
struct ChapterItem {
  ItemKind kind;
  std::string number;  ///< "1.12"
  std::string title;   ///< what it shows or asks
  /// Each command's arguments after `vibra`; outputs are named by -o and land
  /// in the site's folder, standard output is kept beside them.
  std::vector<std::vector<std::string>> commands;
  /// Where the book's text differs from what vibra computes (docs/misprints.md); "" for none.
  std::string note = "";
};

/// Every item, in the chapter's order: figures and exercises each by number,
/// a figure before the exercise of the same number.
const std::vector<ChapterItem>& chapter_items();

/// "fig1.12" or "ex1.12": the key that names one item (--only, the page's anchors, book values).
std::string item_key(const ChapterItem&);
/// "Figure 1.12" or "Exercise 1.12".
std::string item_name(const ChapterItem&);

/// The items --only selects: "" for all; else a comma list of numbers (1.12:
/// the figure and the exercise of that number) or keys (fig1.12, ex1.12).
/// Throws UsageError naming an unknown one.
std::vector<const ChapterItem*> select_items(const std::string& only);

/// The value after -o in a command ("" when it writes no file).
std::string command_output(const std::vector<std::string>& args);

}  // namespace vibra::cli
