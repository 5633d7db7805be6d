// PngSequenceWriter: frames as numbered PNG files, compressed on worker threads.
#pragma once
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "render/encode/png/png_encoder.hpp"  // PngScanlines, which the writer queues
#include "render/output/file_listing.hpp"
#include "render/output/frame_ledger.hpp"
#include "render/output/temporary_file.hpp"

namespace vibra::render {

/// Names of a zero-padded PNG sequence: directory / (prefix + index + suffix).
struct FramePattern {
  std::filesystem::path directory;
  std::string prefix, suffix;
  int digits = 4;
  /// E.g. "frames/tmp_0042.png"; an index wider than `digits` is written in full.
  std::filesystem::path name(long long index) const;
  /// The frame number a file name in `directory` stands for, if the pattern
  /// names it (with `any_digits`, also when its number has another width).
  std::optional<long long> index_of(const std::string& file_name, bool any_digits = false) const;
};

/// What became of files named like a run's frames that the run did not write.
struct EarlierFrames {
  long long removed = 0;  ///< an earlier run's frames, proven by `ledger`
  long long kept = 0;     ///< named like frames, but not provably vibra's
};

/// After a whole render of `count` frames has replaced its set: removes the
/// frames of an earlier run that this one did not write, files named by the
/// same pattern (prefix, digits, suffix) with a number of `count` or more, or
/// with another number of digits, when `ledger` proves vibra wrote them and
/// nobody changed them since. Anything else in the folder stays.
EarlierFrames remove_earlier_frames(const FramePattern&, long long count, const FrameLedger& ledger);

/// Reads a user's pattern: "frames/tmp_%04d.png" (exactly one %d or %0Nd,
/// N in 1..18, in the file name, which ends in .png, any case), or a
/// directory "DIR" or "DIR/" meaning DIR/tmp_%04d.png. The digits widen when
/// frame_count - 1 needs more, so names always sort (10001 frames: 5 digits).
/// A missing directory is allowed (the caller creates it: CreatedDirectory).
/// Throws OutputError for a bad pattern, an unwritable directory, or a file
/// where a directory is needed.
FramePattern parse_frame_pattern(const std::string& pattern, long long frame_count);

/// Writes PNG frames on worker threads: encoding costs more than drawing and
/// frames are independent, so every core compresses. The queue holds at most
/// `threads` frames, so memory stays flat for any number of frames. Frames may
/// finish out of order. They are written into a temporary folder beside
/// their names (TemporaryDirectory) and moved to their names by finish(), so
/// until the run completes an earlier run's frames stay as they were.
class PngSequenceWriter {
 public:
  /// `first_index`: the number of the first frame (a segment of a longer
  /// render numbers its frames as the whole render does). Throws
  /// std::invalid_argument for a non-positive size or thread count.
  PngSequenceWriter(FramePattern, int width, int height, int threads = 2, long long first_index = 0);
  PngSequenceWriter(const PngSequenceWriter&) = delete;
  PngSequenceWriter& operator=(const PngSequenceWriter&) = delete;
  /// Not finished (error, interrupt): drops queued frames, waits for the
  /// workers, then removes the temporary folder with every frame this run
  /// wrote: no partial sequence remains, and earlier frames are untouched.
  /// Never throws.
  ~PngSequenceWriter();

  /// Packs one Cairo ARGB32 frame (width x height, rows `stride` bytes apart)
  /// as PNG scanlines and queues it, waiting while the queue is full. Throws
  /// OutputError if a worker has already failed.
  void write(const std::uint8_t* bgra, int stride);
  /// Waits until every frame is on disk, then moves them to their names;
  /// throws OutputError for the first failure.
  void finish();
  /// Frames accepted by write(); all of them are on disk once finish() returns.
  long long frames_written() const { return queued_ - first_; }
  /// The fingerprints of the frames on disk after finish(), by file name;
  /// none when there are more than a listing holds (kMostListedFiles).
  std::optional<FileListing> written_listing() const;

 private:
  struct Job {
    long long index;
    PngScanlines scanlines;
  };
  void work();
  Fingerprint save(const Job&, std::vector<std::uint8_t>& png) const;
  void stop_workers() noexcept;

  FramePattern pattern_;
  TemporaryDirectory staging_;  ///< where the frames wait for finish()
  int width_, height_;
  size_t capacity_;
  long long first_;
  long long queued_;  ///< the next frame's index
  bool finished_ = false;

  std::mutex mutex_;  // guards everything below
  std::condition_variable work_;      // a job was queued, or stopping
  std::condition_variable progress_;  // a job was taken or done
  std::deque<Job> jobs_;
  std::vector<PngScanlines> spare_;  // recycled: frames cost no allocation
  int busy_ = 0;
  bool stopping_ = false;
  std::string failure_;
  std::vector<Fingerprint> fingerprints_;  ///< by frame, while a listing can hold them
  std::vector<std::thread> workers_;
};

}  // namespace vibra::render
