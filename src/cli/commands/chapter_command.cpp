// Registers `vibra chapter`: the whole of chapter 1 regenerated into a static site, in one command.
#include <memory>

#include "cli/chapter/chapter_site.hpp"
#include "cli/commands.hpp"
#include "cli/option_checks.hpp"

namespace vibra::cli {

void add_chapter_command(CLI::App& app) {
  auto o = std::make_shared<ChapterOptions>();
  CLI::App* cmd = app.add_subcommand(
      "chapter",
      "Regenerate every figure and exercise of chapter 1 into a static site, with the book's numbers beside vibra's");
  add_output_option(*cmd, o->site,
                    "The site's folder (new, empty, or an earlier vibra chapter site, which is replaced)");
  cmd->add_option(
      "--only", o->only,
      "Items to make: numbers (1.12: the figure and the exercise) or keys (fig1.21, ex1.9), comma-separated");
  cmd->add_option("-j,--jobs", o->jobs, "Commands run at once (default: one per core)")
      ->check(ranged("--jobs"));
  cmd->add_flag("--check", o->check,
                "Compare vibra's numbers with the book's; exit 1 naming each that differs (without -o: no site)");
  cmd->add_option("--book-values", o->book_values,
                  "CSV of ITEM,QUANTITY,VALUE lines replacing stored book values (names as the index lists them)");
  cmd->add_flag("-q,--quiet", o->quiet, "No progress or messages");
  cmd->footer(
      "\nExamples:\n"
      "  vibra chapter -o site/ --jobs 2          # the whole chapter; open site/index.html\n"
      "  vibra chapter --only 1.12,1.21 -o part/  # Figures and Exercises 1.12 and 1.21\n"
      "  vibra chapter --check --jobs 2           # exit 1 if a number differs from the book's\n");
  cmd->callback([o] {
    if (const int code = run_chapter(*o)) throw ReportedExit{code};  // --check named each difference
  });
}

}  // namespace vibra::cli
