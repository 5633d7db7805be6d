// A run's rows as a CSV file beside its video (every K-th step), put in place only by commit().
#include "jobs/run_csv_file.hpp"

#include "render/output/output_error.hpp"

namespace vibra::scenes {

RunCsvFile::RunCsvFile(const std::filesystem::path& path, const std::vector<std::string>& columns, long long every)
    : file_(path), every_(every) {
  out_ = std::fopen(file_.path().c_str(), "wb");
  if (!out_) throw render::OutputError("cannot write '" + path.string() + "': choose a writable path");
  csv_ = std::make_unique<CsvWriter>(out_, columns);
}

RunCsvFile::~RunCsvFile() {
  csv_.reset();
  if (out_) std::fclose(out_);
}

void RunCsvFile::write(long long index, bool last, std::span<const double> row) {
  if (index % every_ == 0 || last) csv_->write(row);
}

void RunCsvFile::commit() {
  const bool written = csv_->flush();
  csv_.reset();
  const bool closed = std::fclose(out_) == 0;
  out_ = nullptr;
  if (!written || !closed)
    throw render::OutputError("writing '" + file_.final_path().string() + "' failed (disk full?): free space or choose "
                              "another path");
  file_.commit();
}

}  // namespace vibra::scenes
