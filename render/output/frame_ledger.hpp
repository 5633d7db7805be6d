// FrameLedger: which frames in a shared folder vibra wrote, so a later run removes an earlier run's frames and only those.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "render/output/file_listing.hpp"

namespace vibra::render {

/// A whole run's ledger in a frames folder; a segment starting at frame F
/// keeps its own beside it (kFrameLedgerName + ".F"), so segments running
/// at once never write the same file.
inline constexpr const char* kFrameLedgerName = ".vibra-frames";

/// The frames vibra wrote into a folder that also holds the user's files.
/// Names prove nothing there (a user may keep `tmp_0400.png` of their own):
/// a file counts as vibra's only when a ledger vibra wrote lists it with the
/// size and hash it still has.
class FrameLedger {
 public:
  /// Reads the folder's ledgers; one that is not vibra's counts as none.
  explicit FrameLedger(std::filesystem::path directory);

  /// Whether `name` in the folder is a plain file of this user that a
  /// ledger lists with its present size and hash.
  bool vouches_for(const std::string& name) const;

  /// After a whole run that wrote `written` (none: too many to list): one
  /// ledger of every listed frame still there, this run's included, in
  /// place of the segments' ledgers. A ledger file vibra did not write is
  /// never replaced. Returns a note for the user, or "".
  std::string record_whole_run(const std::optional<FileListing>& written);

  /// After a segment whose first frame is `first`: its own ledger.
  std::string record_segment(long long first, const std::optional<FileListing>& written);

 private:
  std::string write_ledger(const std::filesystem::path& file, const FileListing& listing);

  std::filesystem::path directory_;
  FileListing listed_;                                 ///< every ledger's entries
  std::vector<std::filesystem::path> segment_ledgers_;  ///< read, so a whole run folds them
};

}  // namespace vibra::render
