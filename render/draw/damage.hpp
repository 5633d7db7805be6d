// Damage tracking: the pixel rectangles a frame changed, so the next frame restores its background only there.
#pragma once
#include <utility>
#include <vector>

namespace vibra::render {

/// Pixel rectangle [x0, x1) x [y0, y1).
struct DamageRect {
  int x0, y0, x1, y1;
};

/// Where a picture's pixels may have changed since the last frame: a short
/// list of rectangles, or everything. Between two frames of an animation most
/// of the picture stands still; knowing where it did not lets the canvas
/// restore its background only where the last frame drew, and the video
/// encoder convert only what changed. Rectangles only ever over-approximate:
/// a pixel outside every rectangle is guaranteed unchanged.
class Damage {
 public:
  Damage(int width, int height) : width_(width), height_(height) {}

  /// Adds a box in (fractional) pixels, widened to whole pixels plus `margin`
  /// for antialiasing and clipped to the picture.
  void add(double x0, double y0, double x1, double y1, double margin = 2);
  void add(const Damage& other);
  void add_all() { all_ = true; }
  void clear() { rects_.clear(), all_ = false; }

  bool all() const { return all_; }
  bool empty() const { return !all_ && rects_.empty(); }
  const std::vector<DamageRect>& rects() const { return rects_; }
  /// Whether anything in [x0, x1) x [y0, y1) may have changed.
  bool intersects(int x0, int y0, int x1, int y1) const;
  /// The columns that may have changed in rows [y0, y1): sorted, disjoint
  /// [x0, x1) spans, written into `spans` (reused, so a frame loop does not allocate).
  void spans(int y0, int y1, std::vector<std::pair<int, int>>& spans) const;

 private:
  int width_, height_;
  bool all_ = false;
  std::vector<DamageRect> rects_;
};

}  // namespace vibra::render
