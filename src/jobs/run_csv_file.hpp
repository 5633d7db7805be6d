// A run's rows as a CSV file beside its video (every K-th step), put in place only by commit().
#pragma once
#include <cstdio>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/csv_writer.hpp"
#include "render/output/temporary_file.hpp"

namespace vibra::scenes {

/// A run's rows as a CSV file, every K-th step and the last one, written
/// under a temporary name and put in place only by commit().
class RunCsvFile {
 public:
  /// Throws render::OutputError when the file cannot be created.
  RunCsvFile(const std::filesystem::path& path, const std::vector<std::string>& columns, long long every);
  ~RunCsvFile();
  RunCsvFile(const RunCsvFile&) = delete;
  RunCsvFile& operator=(const RunCsvFile&) = delete;

  /// The row of step `index`; `last` marks the run's final step.
  void write(long long index, bool last, std::span<const double> row);
  /// Flushes, closes and renames into place; throws render::OutputError on a failed write.
  void commit();

 private:
  render::TemporaryFile file_;
  std::FILE* out_ = nullptr;
  std::unique_ptr<CsvWriter> csv_;
  long long every_;
};

}  // namespace vibra::scenes
