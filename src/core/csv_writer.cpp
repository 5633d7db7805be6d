// CsvWriter: rows of doubles as shortest round-trip CSV through one large buffer.
#include "core/csv_writer.hpp"

#include <cerrno>
#include <charconv>
#include <cstring>

namespace vibra {

namespace {
constexpr size_t kBufferSize = 1 << 16;
constexpr size_t kMaxNumber = 32;  // longest to_chars output for a double, with sign and exponent
}  // namespace

CsvWriter::CsvWriter(std::FILE* out, const std::vector<std::string>& columns) : out_(out), buffer_(kBufferSize) {
  for (size_t i = 0; i < columns.size(); ++i) {
    std::string cell = (i ? "," : "") + columns[i];
    std::memcpy(buffer_.data() + used_, cell.data(), cell.size());
    used_ += cell.size();
  }
  buffer_[used_++] = '\n';
}

CsvWriter::~CsvWriter() { flush(); }

void CsvWriter::write(std::span<const double> row) {
  if (used_ + row.size() * (kMaxNumber + 1) + 1 > buffer_.size()) drain();
  char* p = buffer_.data() + used_;
  char* end = buffer_.data() + buffer_.size();
  for (size_t i = 0; i < row.size(); ++i) {
    if (i) *p++ = ',';
    p = std::to_chars(p, end, row[i]).ptr;
  }
  *p++ = '\n';
  used_ = p - buffer_.data();
}

void CsvWriter::drain() {
  errno = 0;
  if (used_ && !failed_ && std::fwrite(buffer_.data(), 1, used_, out_) != used_) fail();
  used_ = 0;
}

bool CsvWriter::flush() {
  drain();
  errno = 0;
  if (!failed_ && std::fflush(out_) != 0) fail();
  return !failed_;
}

void CsvWriter::fail() {
  failed_ = true;
  error_ = errno != 0 ? errno : EIO;
}

}  // namespace vibra
