// `vibra chapter`: the whole chapter's figures and exercises regenerated into a static site, and checked against the
// book.
#pragma once
#include <string>

namespace vibra::cli {

struct ChapterOptions {
  std::string site;         ///< -o SITE: the folder to make; "" with --check alone
  std::string only;         ///< --only 1.12,fig1.21; "" for all
  int jobs = 0;             ///< commands run at once; 0: one per core
  bool check = false;       ///< compare vibra's numbers with the book's; a difference is exit 1
  std::string book_values;  ///< --book-values FILE: replacements for the stored book values
  bool quiet = false;
};

/// Runs the chapter's commands into a folder beside SITE, writes its index,
/// and puts the folder in SITE's place whole (an earlier site of vibra's is
/// replaced; any other folder is refused). Returns 0, or 1 when --check
/// found a number that differs from the book's (each named on stderr).
/// Throws UsageError / OutputError / Interrupted; nothing is left at SITE then.
int run_chapter(const ChapterOptions&);

/// The file in a site that lists what vibra wrote there: a folder holding it,
/// and nothing it does not list, is vibra's to replace.
extern const char* const kSiteManifest;

}  // namespace vibra::cli
