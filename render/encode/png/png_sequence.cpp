// PngSequenceWriter: frames as numbered PNG files, compressed on worker threads.
#include "render/encode/png/png_sequence.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <system_error>

#include "render/output/created_directory.hpp"
#include "render/output/output_error.hpp"
#include "render/output/stop_signal.hpp"
#include "render/output/temporary_file.hpp"

namespace fs = std::filesystem;

namespace vibra::render {

namespace {
constexpr int kMaxDigits = 18;  // a long long index has at most 19

[[noreturn]] void bad_pattern(const std::string& pattern, const std::string& problem) {
  throw OutputError("frame pattern '" + pattern + "' " + problem +
                    ": use e.g. frames/tmp_%04d.png, or a directory such as frames/");
}

bool ends_with_png(const std::string& text) {
  if (text.size() < 4) return false;
  std::string tail = text.substr(text.size() - 4);
  for (char& c : tail) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return tail == ".png";
}

/// The width of the "%d" (1) or "%0Nd" (N) directive at text[at] == '%', and
/// where it ends; 0 when it is neither.
int directive_width(const std::string& text, size_t at, size_t& end) {
  size_t pos = at + 1;
  int width = 1;
  if (pos < text.size() && text[pos] == '0') {
    width = 0;
    while (++pos < text.size() && std::isdigit(static_cast<unsigned char>(text[pos])) && width <= kMaxDigits)
      width = width * 10 + (text[pos] - '0');
    if (width < 1 || width > kMaxDigits) return 0;
  }
  if (pos >= text.size() || text[pos] != 'd') return 0;
  end = pos + 1;
  return width;
}

int decimal_digits(long long n) {
  int digits = 1;
  for (; n >= 10; n /= 10) ++digits;
  return digits;
}
}  // namespace

fs::path FramePattern::name(long long index) const {
  char number[32];
  std::snprintf(number, sizeof number, "%0*lld", digits, index);
  return directory / (prefix + number + suffix);
}

std::optional<long long> FramePattern::index_of(const std::string& file_name, bool any_digits) const {
  if (file_name.size() <= prefix.size() + suffix.size() || !file_name.starts_with(prefix) || !file_name.ends_with(suffix))
    return std::nullopt;
  const std::string number = file_name.substr(prefix.size(), file_name.size() - prefix.size() - suffix.size());
  if (number.size() > kMaxDigits + 1 || !std::all_of(number.begin(), number.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return std::nullopt;
  long long index = 0;
  if (std::from_chars(number.data(), number.data() + number.size(), index).ec != std::errc()) return std::nullopt;
  if (!any_digits && name(index).filename() != file_name) return std::nullopt;  // another number of digits
  return index;
}

FramePattern parse_frame_pattern(const std::string& pattern, long long frame_count) {
  FramePattern p;
  const size_t percent = pattern.find('%');
  if (percent == std::string::npos) {
    std::error_code ec;
    if (pattern.empty()) bad_pattern(pattern, "is empty");
    // "out.png" is more likely a forgotten %04d than a directory name.
    if (ends_with_png(pattern) && !fs::is_directory(pattern, ec)) bad_pattern(pattern, "has no %d for the frame number");
    p.directory = pattern;
    p.prefix = "tmp_";
    p.suffix = ".png";
  } else {
    const fs::path path(pattern);
    const std::string file = path.filename().string();
    const size_t at = file.find('%');
    size_t end = 0;
    const int width = at == std::string::npos ? 0 : directive_width(file, at, end);
    if (width == 0 || pattern.find('%', percent + 1) != std::string::npos)
      bad_pattern(pattern, "needs exactly one %d or %0Nd (N up to 18) in the file name");
    p.directory = path.has_parent_path() ? path.parent_path() : fs::path(".");
    p.prefix = file.substr(0, at);
    p.suffix = file.substr(end);
    p.digits = width;
    if (!ends_with_png(p.suffix)) bad_pattern(pattern, "must end in .png");
  }
  require_creatable_directory(p.directory);  // the sink creates it (CreatedDirectory)
  // Every index gets the same width, so the names sort in frame order.
  p.digits = std::max(p.digits, decimal_digits(std::max(0LL, frame_count - 1)));
  return p;
}

EarlierFrames remove_earlier_frames(const FramePattern& p, long long count, const FrameLedger& ledger) {
  EarlierFrames result;
  std::error_code ec;
  long long seen = 0;
  for (const auto& entry : fs::directory_iterator(p.directory, ec)) {
    if ((++seen & 0xff) == 0) throw_if_stop_requested();
    const std::string name = entry.path().filename().string();
    const std::optional<long long> number = p.index_of(name, true);
    if (!number || (*number < count && p.index_of(name, false))) continue;  // not named like a frame, or this run's
    std::error_code ignored;
    if (ledger.vouches_for(name) && fs::remove(entry.path(), ignored)) ++result.removed;
    else ++result.kept;
  }
  return result;
}

std::optional<FileListing> PngSequenceWriter::written_listing() const {
  if (frames_written() > static_cast<long long>(kMostListedFiles)) return std::nullopt;
  FileListing listing;
  for (long long i = 0; i < static_cast<long long>(fingerprints_.size()) && i < frames_written(); ++i)
    listing.emplace(pattern_.name(first_ + i).filename().string(), fingerprints_[static_cast<size_t>(i)]);
  return listing;
}

PngSequenceWriter::PngSequenceWriter(FramePattern pattern, int width, int height, int threads, long long first_index)
    : pattern_(std::move(pattern)),
      staging_(pattern_.directory, "frames"),
      width_(width),
      height_(height),
      capacity_(std::max(threads, 1)),
      first_(first_index),
      queued_(first_index) {
  if (width <= 0 || height <= 0 || threads <= 0)
    throw std::invalid_argument("PngSequenceWriter needs a positive width, height and thread count");
  try {
    for (int i = 0; i < threads; ++i) workers_.emplace_back([this] { work(); });
  } catch (...) {
    stop_workers();
    throw;
  }
}

PngSequenceWriter::~PngSequenceWriter() { stop_workers(); }  // then staging_ removes this run's frames

void PngSequenceWriter::write(const std::uint8_t* bgra, int stride) {
  if (finished_) throw std::logic_error("PngSequenceWriter::write after finish");
  PngScanlines scanlines;
  std::unique_lock lock(mutex_);
  if (!spare_.empty()) {
    scanlines = std::move(spare_.back());
    spare_.pop_back();
  }
  lock.unlock();
  // Packing is the copy the caller needs anyway (its surface is redrawn
  // next); done before waiting for room, so it overlaps the workers' compression.
  pack_png_scanlines(bgra, width_, height_, stride, scanlines);
  lock.lock();
  progress_.wait(lock, [&] { return jobs_.size() < capacity_ || !failure_.empty(); });
  if (!failure_.empty()) throw OutputError(failure_);
  jobs_.push_back({queued_++, std::move(scanlines)});
  lock.unlock();
  work_.notify_one();
}

void PngSequenceWriter::finish() {
  {
    std::unique_lock lock(mutex_);
    progress_.wait(lock, [&] { return (jobs_.empty() && busy_ == 0) || !failure_.empty(); });
    if (!failure_.empty()) throw OutputError(failure_);
  }
  stop_workers();
  staging_.move_files_into_location();  // not interrupted: the set is replaced whole
  finished_ = true;
}

void PngSequenceWriter::stop_workers() noexcept {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    jobs_.clear();
  }
  work_.notify_all();
  for (auto& worker : workers_) worker.join();
  workers_.clear();
}

void PngSequenceWriter::work() {
  std::vector<std::uint8_t> png;  // this worker's output buffer, reused
  std::unique_lock lock(mutex_);
  for (;;) {
    work_.wait(lock, [&] { return stopping_ || !jobs_.empty(); });
    if (stopping_) return;
    Job job = std::move(jobs_.front());
    jobs_.pop_front();
    ++busy_;
    lock.unlock();
    progress_.notify_all();  // room in the queue

    std::string error;
    Fingerprint written;
    try {
      written = save(job, png);
    } catch (const OutputError& e) {
      error = e.what();
    } catch (const std::exception& e) {
      error = "cannot write " + pattern_.name(job.index).string() + ": " + e.what();
    }

    lock.lock();
    --busy_;
    spare_.push_back(std::move(job.scanlines));
    if (const long long slot = job.index - first_; error.empty() && slot < static_cast<long long>(kMostListedFiles)) {
      if (fingerprints_.size() <= static_cast<size_t>(slot)) fingerprints_.resize(static_cast<size_t>(slot) + 1);
      fingerprints_[static_cast<size_t>(slot)] = written;
    }
    if (!error.empty() && failure_.empty())
      failure_ = std::move(error);
    progress_.notify_all();
  }
}

Fingerprint PngSequenceWriter::save(const Job& job, std::vector<std::uint8_t>& png) const {
  const std::size_t size = encode_png(job.scanlines, png);
  const fs::path name = pattern_.name(job.index);
  const fs::path file = staging_.path() / name.filename();
  std::FILE* out = std::fopen(file.c_str(), "wb");
  if (!out)
    throw OutputError("cannot create '" + file.string() + "': " + std::generic_category().message(errno) +
                      ": choose a writable directory");
  bool ok = std::fwrite(png.data(), 1, size, out) == size;
  int error = errno;
  if (std::fclose(out) != 0 && ok) ok = false, error = errno;
  if (!ok)
    throw OutputError("writing '" + name.string() + "' failed: " + std::generic_category().message(error) +
                      ": free disk space or choose another directory");
  return fingerprint_of(png.data(), size);
}

}  // namespace vibra::render
