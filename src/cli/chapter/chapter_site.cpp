// Builds the chapter site: plans the commands, runs them, reads the book's numbers, writes the index, places the site.
#include "cli/chapter/chapter_site.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <thread>

#include "cli/chapter/chapter_index.hpp"
#include "cli/chapter/chapter_jobs.hpp"
#include "cli/chapter/chapter_tables.hpp"
#include "cli/wrote_message.hpp"
#include "core/error.hpp"
#include "core/input/quoted_value.hpp"
#include "core/stop_flag.hpp"
#include "render/output/output_error.hpp"
#include "render/output/ownership_manifest.hpp"
#include "render/output/standard_output.hpp"
#include "render/output/temporary_file.hpp"
#include "render/page/html_page.hpp"

namespace vibra::cli {

namespace fs = std::filesystem;

namespace {
// Columns that hold timings, not results: masked so a second run is byte for byte the same.
const std::vector<std::string> kTimingColumns = {"cpu_s"};

/// The commands to run: each distinct command once (Figures 1.7 and 1.8 share
/// one), in the chapter's order; `job_of[key][k]` is item key's command k's job.
std::vector<ChapterJob> plan_jobs(const std::vector<const ChapterItem*>& items,
                                  std::map<std::string, std::vector<size_t>>& job_of) {
  std::vector<ChapterJob> jobs;
  for (const ChapterItem* item : items)
    for (size_t k = 0; k < item->commands.size(); ++k) {
      const auto& args = item->commands[k];
      auto same = std::find_if(jobs.begin(), jobs.end(), [&](const ChapterJob& job) { return job.args == args; });
      if (same == jobs.end())
        same =
            jobs.insert(jobs.end(), {args, item_key(*item) + "-" + std::to_string(k + 1) + ".txt", item_name(*item)});
      job_of[item_key(*item)].push_back(static_cast<size_t>(same - jobs.begin()));
    }
  return jobs;
}

/// Refuses a SITE that is not vibra's to replace: a file, a link, or a
/// folder that is neither empty nor proven vibra's by the manifest of
/// names, sizes and hashes vibra writes last (render/output/ownership_manifest.hpp).
void check_site_folder(const fs::path& site) {
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(site, ec);
  if (!fs::exists(status)) return;
  const std::string named = quoted_value(site.string());
  if (!fs::is_directory(status))
    throw UsageError("-o " + named + " is not a folder: give a new folder for the site, e.g. -o site/");
  if (fs::is_empty(site, ec) && !ec) return;
  if (const std::string why = render::why_not_vibras(site); !why.empty())
    throw UsageError("-o " + named + " " + why + ": give a new or empty folder, or move it");
}

/// A job's standard output, timings masked; "" (and the file removed) when it printed nothing.
std::string kept_text(const fs::path& file) {
  const std::string text = render::read_text_file(file);
  if (text.empty()) {
    fs::remove(file);
    return "";
  }
  const std::string masked = mask_columns(text, kTimingColumns);
  if (masked != text) render::write_text_file(file, masked);
  return masked;
}

NumberResult compare(const BookNumber& number, const std::string& text) {
  const std::string cell = table_cell(text, number.column, number.row);
  char* end = nullptr;
  const double vibra = std::strtod(cell.c_str(), &end), book = std::strtod(number.book.c_str(), nullptr);
  const bool read = !cell.empty() && *end == '\0';
  return {&number, cell, read && std::abs(vibra - book) <= number.tolerance * std::abs(book)};
}
}  // namespace

namespace {
/// Each item's commands with what they left in `folder`, and its book numbers beside vibra's.
std::vector<ItemResult> collect_results(const std::vector<const ChapterItem*>& items,
                                        const std::vector<ChapterJob>& jobs,
                                        const std::map<std::string, std::vector<size_t>>& job_of,
                                        const std::vector<BookNumber>& numbers, const fs::path& folder) {
  std::vector<std::string> texts(jobs.size());
  for (size_t j = 0; j < jobs.size(); ++j) texts[j] = kept_text(folder / jobs[j].output_text);
  std::vector<ItemResult> results;
  for (const ChapterItem* item : items) {
    ItemResult result{item, {}, {}};
    const auto found = job_of.find(item_key(*item));
    const std::vector<size_t> none, &its_jobs = found == job_of.end() ? none : found->second;
    for (size_t j : its_jobs)
      result.commands.push_back(
          {jobs[j].args, command_output(jobs[j].args), texts[j].empty() ? "" : jobs[j].output_text, texts[j]});
    for (const BookNumber& number : numbers)
      if (number.item == item_key(*item) && number.command < its_jobs.size())
        result.numbers.push_back(compare(number, texts[its_jobs[number.command]]));
    results.push_back(std::move(result));
  }
  return results;
}

/// index.html; the manifest of the site's files (names, sizes, hashes) is
/// written last, when the staging folder is sealed.
void write_index(const std::vector<ItemResult>& results, const std::string& only, const fs::path& folder) {
  render::write_text_file(folder / "index.html", chapter_index_html(results, only));
}

/// --check: each number that differs on stderr, one line each; whether all agree.
bool report_check(const std::vector<ItemResult>& results, bool quiet) {
  size_t total = 0, differ = 0;
  for (const ItemResult& result : results)
    for (const NumberResult& n : result.numbers) {
      ++total;
      if (n.agrees) continue;
      ++differ;
      std::fprintf(stderr, "vibra: chapter --check: %s %s: the book gives %s, vibra %s (tolerance %g%%)\n",
                   n.number->item.c_str(), quantity_name(*n.number).c_str(), n.number->book.c_str(),
                   n.vibra.empty() ? "nothing (not in its output)" : n.vibra.c_str(), n.number->tolerance * 100);
    }
  if (!quiet && differ == 0)
    std::fprintf(stderr, "vibra: chapter --check: all %zu of the book's numbers agree\n", total);
  return differ == 0;
}

/// SITE without trailing slashes ("site/" names the folder "site").
fs::path site_path(std::string site) {
  while (site.size() > 1 && site.back() == '/') site.pop_back();
  return site;
}
}  // namespace

int run_chapter(const ChapterOptions& o) {
  if (o.site == "-")
    throw UsageError("-o - would send the site to standard output: the site is a folder, give e.g. -o site/");
  if (o.site.empty() && !o.check)
    throw UsageError("vibra chapter needs a folder for the site: add -o SITE/ (or --check alone to compare only)");
  if (o.jobs < 0 || o.jobs > 64)  // the option's check says this first; 0 is the default, one per core
    throw UsageError("--jobs " + std::to_string(o.jobs) + " is out of range: give 1 to 64");
  const std::vector<const ChapterItem*> items = select_items(o.only);
  const std::vector<BookNumber> numbers = book_numbers_with(o.book_values);
  const fs::path site = site_path(o.site);
  if (!o.site.empty()) check_site_folder(site);
  render::TemporaryDirectory folder(o.site.empty() ? fs::temp_directory_path() : site.parent_path(),
                                    o.site.empty() ? "vibra-chapter" : site.filename().string());
  std::map<std::string, std::vector<size_t>> job_of;
  const std::vector<ChapterJob> jobs = plan_jobs(items, job_of);
  const int cores = static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 64u));
  run_chapter_jobs(jobs, fs::absolute(folder.path()), o.jobs > 0 ? o.jobs : cores, o.quiet);
  const std::vector<ItemResult> results = collect_results(items, jobs, job_of, numbers, folder.path());
  if (!o.site.empty()) {
    write_index(results, o.only, folder.path());
    folder.replace(site);
    say_wrote(o.quiet, o.site + " (index.html: " + std::to_string(items.size()) + " figures and exercises)");
  }
  return !o.check || report_check(results, o.quiet) ? 0 : 1;
}

}  // namespace vibra::cli
