// CsvWriter: rows of doubles as shortest round-trip CSV through one large buffer.
#pragma once
#include <cstdio>
#include <span>
#include <string>
#include <vector>

namespace vibra {

/// Writes rows of doubles as CSV in the shortest form that reads back to the
/// same double (std::to_chars), through one large buffer.
class CsvWriter {
 public:
  /// Writes the header line. `out` stays owned by the caller.
  CsvWriter(std::FILE* out, const std::vector<std::string>& columns);
  ~CsvWriter();
  void write(std::span<const double> row);
  /// Flushes; returns false if any write failed (disk full, closed pipe).
  bool flush();
  /// A write has failed: stop producing rows.
  bool failed() const { return failed_; }
  /// The errno of the failed write, or 0.
  int error() const { return error_; }

 private:
  void drain();
  void fail();  ///< after a failed stdio call: keeps its errno
  std::FILE* out_;
  std::vector<char> buffer_;
  size_t used_ = 0;
  bool failed_ = false;
  int error_ = 0;
};

}  // namespace vibra
