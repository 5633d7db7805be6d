// Canvas: a Cairo surface (image, SVG or PDF) in pixels and world units that records where each stroke lands (damage).
#pragma once
#include <cairo.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <utility>

#include "render/draw/color.hpp"
#include "render/draw/damage.hpp"

namespace vibra::render {

/// How every drawing context rasterizes shapes: the canvas and the tiles it
/// pastes (labels, trails, roads) alike, so that a pasted piece matches a
/// drawn one. Not CAIRO_ANTIALIAS_FAST, though it strokes twice as fast:
/// Cairo 1.16's 4x4-sample rasterizer behind it corrupts the heap on some
/// long paths (a windowed orbit's panels aborted in free()).
inline constexpr cairo_antialias_t kShapeAntialias = CAIRO_ANTIALIAS_GOOD;

class LabelCache;
struct DrawingRecord;

using Point = Eigen::Vector2d;

/// A rectangle in pixels: x, y of the top-left corner, width, height.
struct PixelRect {
  double x = 0, y = 0, w = 0, h = 0;
  Point center() const { return {x + w / 2, y + h / 2}; }
};

/// Pixels per 720p pixel for a picture `height` pixels high: line widths and
/// fonts are multiplied by it. Never below 0.7 down to 360 pixels, so labels
/// stay readable on frames such as 640x360; below that the picture is a
/// thumbnail, the 360-pixel picture made smaller as a whole (at 320x180 its
/// text is too small to read, but nothing covers the drawing).
inline double scale_for_height(int height) { return height >= 360 ? std::max(0.7, height / 720.0) : 0.7 * height / 360.0; }

/// A Cairo drawing surface: an ARGB32 image for frames, or an SVG/PDF file for
/// vector stills. Line widths and font sizes are given at 720p and scaled with
/// the canvas height, so a picture looks the same at 640x360 and 3840x2160.
class Canvas {
 public:
  /// Throws OutputError for sizes outside 1..8192.
  static Canvas image(int width, int height);
  static Canvas svg(const std::filesystem::path& file, int width, int height);
  static Canvas pdf(const std::filesystem::path& file, int width, int height);

  cairo_t* cr() const { return cr_.get(); }
  int width() const { return width_; }
  int height() const { return height_; }
  double scale() const { return scale_for_height(height_); }
  cairo_surface_t* surface() const { return surface_.get(); }
  /// Unique to this canvas and its copies, never reused (unlike the surface's
  /// address, which a canvas created later may get).
  std::uint64_t id() const { return id_; }

  /// Image canvases only: the pixels (BGRA in memory on little-endian) after flush().
  const std::uint8_t* data() const;
  int stride() const;
  void flush() const;
  /// Vector canvases: finish writing the file; throws OutputError on failure.
  void finish();
  /// Image canvases: labels laid out and drawn once, pasted after (see
  /// LabelCache); null for a vector canvas, where text stays text.
  LabelCache* labels() const { return labels_.get(); }
  /// Image canvases: whether labels are kept (the default). Off, every label
  /// is set afresh, as on a vector canvas: the reference that tests hold the
  /// kept images to.
  void keep_labels(bool keep);

  /// Paints every pixel with the colour (alpha included). A fully transparent
  /// colour on an SVG or PDF page draws nothing: the page is already empty.
  void clear(Color);

  /// Stroke and fills, noting first where they land (see Damage). A plain
  /// stroke on an image is drawn by raster_stroke, any other by Cairo.
  /// Every drawing of a frame goes through these or mark_drawn().
  void stroke();
  void fill();
  void fill_preserve();
  /// Notes a box in user space that is about to be drawn.
  void mark_drawn(double x0, double y0, double x1, double y1);

  /// From now on, every box noted drawn (a stroke's, a fill's, a text's)
  /// also widens `extent`, in device pixels, on any canvas (nullptr: stop).
  /// Returns the box that was widened before, so that scopes nest.
  Eigen::AlignedBox2d* extent_into(Eigen::AlignedBox2d* extent) { return std::exchange(extent_, extent); }

  /// From now on, every stroke, fill and text goes into `record`'s outline,
  /// and labels asked for wait there to be placed (nullptr: drawn at once).
  void record_into(DrawingRecord* record) { record_ = record; }
  DrawingRecord* record() const { return record_; }

  /// Frames of an animation: from now on, note where drawing lands.
  void track_damage() { tracking_ = true; }
  bool tracks_damage() const { return tracking_; }
  /// A new frame: what was drawn becomes the last frame's drawing.
  void begin_frame();
  /// What the last frame drew over its background (to be restored).
  const Damage& drawn_last_frame() const { return drawn_last_frame_; }
  /// What this frame drew so far, over its background.
  const Damage& drawn() const { return drawn_; }
  /// Notes background restored in `region` (all of it when region.all()).
  void mark_restored(const Damage& region) { restored_.add(region); }
  /// Where this frame's pixels may differ from the last frame's: what was
  /// restored and what was drawn.
  Damage changed() const;

 private:
  Canvas(cairo_surface_t*, int width, int height);
  /// Notes the current path's extent, widened by `widen` user units.
  void mark_path(double widen);
  std::shared_ptr<cairo_surface_t> surface_;
  std::shared_ptr<cairo_t> cr_;
  int width_, height_;
  std::uint64_t id_;
  bool tracking_ = false;
  Damage drawn_, drawn_last_frame_, restored_;
  std::shared_ptr<LabelCache> labels_;
  DrawingRecord* record_ = nullptr;
  Eigen::AlignedBox2d* extent_ = nullptr;
};

/// Intersects the clip with `r` rounded to whole device pixels. Cairo clips
/// to such a rectangle without a mask, and the strokes inside it stay plain
/// ones (see raster_stroke); within half a pixel of the rectangle given.
void clip_to_pixels(cairo_t* cr, const PixelRect& r);

/// Maps world coordinates (y up, equal aspect) into a pixel rectangle (y down),
/// fitting a world box and centring it.
class WorldView {
 public:
  WorldView(const Eigen::AlignedBox2d& world, const PixelRect& pixels);
  /// The world `sizes` around `centre`: a view that follows a body keeps its
  /// sizes exact, where a box's max - min would vary in its last bits as it
  /// moves (and with it the zoom and every row of the picture).
  WorldView(const Point& centre, const Point& sizes, const PixelRect& pixels);
  Point to_pixel(const Point& world) const { return transform_ * world; }
  /// Pixels per world unit.
  double zoom() const { return zoom_; }

 private:
  Eigen::Affine2d transform_;
  double zoom_;
};

}  // namespace vibra::render
