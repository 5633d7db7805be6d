// FrameLedger: reading the ledgers of a frames folder, vouching for a file, and recording a run's frames.
#include "render/output/frame_ledger.hpp"

#include "core/stop_flag.hpp"
#include "render/output/ownership_manifest.hpp"

namespace fs = std::filesystem;

namespace vibra::render {

namespace {
/// Whether the file name is a segment's ledger (".vibra-frames.F").
bool is_segment_ledger(const std::string& name) {
  const std::string prefix = std::string(kFrameLedgerName) + ".";
  return name.size() > prefix.size() && name.starts_with(prefix) &&
         name.find_first_not_of("0123456789", prefix.size()) == std::string::npos;
}

/// A ledger file that exists but is not one vibra wrote: it stays as it is.
bool is_foreign(const fs::path& file) {
  std::error_code ec;
  return fs::exists(fs::symlink_status(file, ec)) && !read_file_listing(file);
}
}  // namespace

FrameLedger::FrameLedger(fs::path directory) : directory_(std::move(directory)) {
  if (std::optional<FileListing> whole = read_file_listing(directory_ / kFrameLedgerName)) listed_ = std::move(*whole);
  std::error_code ec;
  long long seen = 0;
  for (const auto& entry : fs::directory_iterator(directory_, ec)) {
    if ((++seen & 0xff) == 0) throw_if_stop_requested();
    if (!is_segment_ledger(entry.path().filename().string())) continue;
    const std::optional<FileListing> segment = read_file_listing(entry.path());
    if (!segment) continue;
    // A segment wrote its frames after the last whole run (which folds and
    // removes the segments' ledgers), so its entries are the newer ones.
    for (const auto& [name, fingerprint] : *segment) listed_[name] = fingerprint;
    segment_ledgers_.push_back(entry.path());
  }
}

bool FrameLedger::vouches_for(const std::string& name) const {
  const auto found = listed_.find(name);
  if (found == listed_.end()) return false;
  const fs::path file = directory_ / name;
  std::error_code ec;
  return why_unreadable(file).empty() && fs::is_regular_file(fs::symlink_status(file, ec)) &&
         fingerprint_file(file) == found->second;
}

std::string FrameLedger::write_ledger(const fs::path& file, const FileListing& listing) {
  if (is_foreign(file))
    return "kept " + file.filename().string() + ", which vibra did not write: these frames are not recorded as vibra's";
  if (listing.size() > kMostListedFiles) return "";  // too many to list: a later run removes none of them
  write_file_listing(file, listing, "the ledger of the frames vibra wrote");
  return "";
}

std::string FrameLedger::record_whole_run(const std::optional<FileListing>& written) {
  FileListing still_there = written.value_or(FileListing{});
  long long looked = 0;
  for (const auto& [name, fingerprint] : listed_) {
    if ((++looked & 0xfff) == 0) throw_if_stop_requested();
    std::error_code ec;
    if (!still_there.count(name) && fs::exists(fs::symlink_status(directory_ / name, ec)))
      still_there.emplace(name, fingerprint);
  }
  const std::string note = write_ledger(directory_ / kFrameLedgerName, still_there);
  if (!note.empty()) return note;
  for (const fs::path& folded : segment_ledgers_) {  // read as vibra's, now in the whole run's ledger
    std::error_code ignored;
    if (read_file_listing(folded)) fs::remove(folded, ignored);
  }
  return "";
}

std::string FrameLedger::record_segment(long long first, const std::optional<FileListing>& written) {
  const fs::path file = directory_ / (std::string(kFrameLedgerName) + "." + std::to_string(first));
  FileListing listing = read_file_listing(file).value_or(FileListing{});
  if (written)
    for (const auto& [name, fingerprint] : *written) listing[name] = fingerprint;
  return write_ledger(file, listing);
}

}  // namespace vibra::render
