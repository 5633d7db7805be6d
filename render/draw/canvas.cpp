// Canvas: a Cairo surface (image, SVG or PDF) in pixels and world units that records where each stroke lands (damage).
#include "render/draw/canvas.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <new>
#include <string>

#include "render/draw/label_cache.hpp"
#include "render/draw/stroke_raster.hpp"
#include "render/encode/huge_pages.hpp"
#include "render/labels/drawing_record.hpp"
#include "render/output/output_error.hpp"

namespace vibra::render {

namespace {
constexpr int kMaxSide = 8192;
std::atomic<std::uint64_t> next_canvas_id{1};

void check_size(int width, int height) {
  if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide)
    throw OutputError("size " + std::to_string(width) + "x" + std::to_string(height) +
                      " is out of range: width and height must be 1..8192, e.g. --size 1280x720");
}
}  // namespace

Canvas::Canvas(cairo_surface_t* surface, int width, int height)
    : surface_(surface, cairo_surface_destroy), width_(width), height_(height), id_(next_canvas_id++),
      drawn_(width, height), drawn_last_frame_(width, height), restored_(width, height) {
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS)
    throw OutputError(std::string("cannot create the drawing surface: ") +
                      cairo_status_to_string(cairo_surface_status(surface)));
  cr_.reset(cairo_create(surface), cairo_destroy);
  cairo_set_antialias(cr_.get(), kShapeAntialias);
  cairo_set_line_join(cr_.get(), CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr_.get(), CAIRO_LINE_CAP_ROUND);
  keep_labels(true);
}

void Canvas::keep_labels(bool keep) {
  // Labels may keep as many bytes as the picture has, and at least 4 MiB.
  if (keep && cairo_surface_get_type(surface()) == CAIRO_SURFACE_TYPE_IMAGE)
    labels_ = std::make_shared<LabelCache>(std::max(std::size_t(4) << 20, std::size_t(4) * width_ * height_));
  else
    labels_.reset();
}

Canvas Canvas::image(int width, int height) {
  check_size(width, height);
  // Pixels in huge pages (see huge_pages.hpp), owned by the surface.
  using Pixels = HugePageArray<unsigned char>;
  const int stride = cairo_format_stride_for_width(CAIRO_FORMAT_ARGB32, width);
  std::unique_ptr<Pixels> pixels;
  try {
    pixels = std::make_unique<Pixels>(std::size_t(stride) * height);
  } catch (const std::bad_alloc&) {
    throw OutputError("cannot create the drawing surface: out of memory for " + std::to_string(width) + "x" +
                      std::to_string(height) + " pixels: choose a smaller --size");
  }
  std::memset(pixels->data(), 0, pixels->size());  // transparent, as cairo_image_surface_create
  cairo_surface_t* surface =
      cairo_image_surface_create_for_data(pixels->data(), CAIRO_FORMAT_ARGB32, width, height, stride);
  static const cairo_user_data_key_t kPixels{};
  if (cairo_surface_status(surface) == CAIRO_STATUS_SUCCESS) {
    if (cairo_surface_set_user_data(surface, &kPixels, pixels.get(),
                                    [](void* p) { delete static_cast<Pixels*>(p); }) !=
        CAIRO_STATUS_SUCCESS) {
      cairo_surface_destroy(surface);
      throw std::bad_alloc();
    }
    pixels.release();
  }
  return Canvas(surface, width, height);  // an error surface throws there
}

Canvas Canvas::svg(const std::filesystem::path& file, int width, int height) {
  check_size(width, height);
  return Canvas(cairo_svg_surface_create(file.c_str(), width, height), width, height);
}

Canvas Canvas::pdf(const std::filesystem::path& file, int width, int height) {
  check_size(width, height);
  return Canvas(cairo_pdf_surface_create(file.c_str(), width, height), width, height);
}

const std::uint8_t* Canvas::data() const { return cairo_image_surface_get_data(surface_.get()); }
int Canvas::stride() const { return cairo_image_surface_get_stride(surface_.get()); }
void Canvas::flush() const { cairo_surface_flush(surface_.get()); }

void Canvas::finish() {
  cairo_surface_finish(surface_.get());
  if (cairo_surface_status(surface_.get()) != CAIRO_STATUS_SUCCESS)
    throw OutputError(std::string("writing the picture failed: ") +
                      cairo_status_to_string(cairo_surface_status(surface_.get())) + " (disk full? unwritable?)");
}

void Canvas::clear(Color c) {
  // A vector page starts empty: a transparent clear adds no rectangle to it.
  if (c.a <= 0 && cairo_surface_get_type(surface()) != CAIRO_SURFACE_TYPE_IMAGE) return;
  if (tracking_) drawn_.add_all();
  cairo_save(cr());
  cairo_set_source_rgba(cr(), c.r, c.g, c.b, c.a);
  cairo_set_operator(cr(), CAIRO_OPERATOR_SOURCE);
  cairo_paint(cr());
  cairo_restore(cr());
}

void Canvas::mark_drawn(double x0, double y0, double x1, double y1) {
  if (!tracking_ && !extent_) return;
  // The box's corners in device pixels: the user space may be scaled or rotated.
  double xs[4] = {x0, x1, x0, x1}, ys[4] = {y0, y0, y1, y1};
  for (int i = 0; i < 4; ++i) cairo_user_to_device(cr(), &xs[i], &ys[i]);
  const double left = *std::min_element(xs, xs + 4), right = *std::max_element(xs, xs + 4);
  const double top = *std::min_element(ys, ys + 4), bottom = *std::max_element(ys, ys + 4);
  if (extent_) extent_->extend(Eigen::AlignedBox2d(Point(left, top), Point(right, bottom)));
  if (tracking_) drawn_.add(left, top, right, bottom);
}

void Canvas::mark_path(double widen) {
  if (!tracking_ && !extent_) return;
  double x0, y0, x1, y1;
  cairo_path_extents(cr(), &x0, &y0, &x1, &y1);
  if (x0 == 0 && y0 == 0 && x1 == 0 && y1 == 0) return;  // empty path: nothing drawn
  mark_drawn(x0 - widen, y0 - widen, x1 + widen, y1 + widen);
}

// A stroke reaches half the line width beyond the path with round joins and
// caps; a whole width leaves room for square caps and short miters.
void Canvas::stroke() {
  // No line thinner than a pixel: below one, antialiasing only greys it, and
  // a thumbnail's axes, hatching and coils faded to nothing.
  if (const double width = cairo_get_line_width(cr()); width > 0 && width < 1) cairo_set_line_width(cr(), 1);
  if (record_) record_->outline.add_stroke(cr(), record_->kind);
  mark_path(cairo_get_line_width(cr()));
  if (!raster_stroke(cr())) cairo_stroke(cr());
}

void Canvas::fill() {
  if (record_) record_->outline.add_fill(cr(), record_->kind);
  mark_path(0);
  cairo_fill(cr());
}

void Canvas::fill_preserve() {
  if (record_) record_->outline.add_fill(cr(), record_->kind);
  mark_path(0);
  cairo_fill_preserve(cr());
}

void Canvas::begin_frame() {
  std::swap(drawn_last_frame_, drawn_);
  drawn_.clear();
  restored_.clear();
}

Damage Canvas::changed() const {
  Damage changed = restored_;
  changed.add(drawn_);
  return changed;
}

WorldView::WorldView(const Eigen::AlignedBox2d& world, const PixelRect& pixels)
    : WorldView(world.center(), world.sizes(), pixels) {}

WorldView::WorldView(const Point& c, const Point& size, const PixelRect& pixels) {
  zoom_ = std::min(pixels.w / size.x(), pixels.h / size.y());
  const Point p = pixels.center();
  // x' = p.x + zoom (x - c.x), y' = p.y - zoom (y - c.y): y flips to point down.
  transform_.matrix() << zoom_, 0, p.x() - zoom_ * c.x(), 0, -zoom_, p.y() + zoom_ * c.y(), 0, 0, 1;
}

void clip_to_pixels(cairo_t* cr, const PixelRect& r) {
  double x0 = r.x, y0 = r.y, x1 = r.x + r.w, y1 = r.y + r.h;
  cairo_user_to_device(cr, &x0, &y0);
  cairo_user_to_device(cr, &x1, &y1);
  x0 = std::round(x0), y0 = std::round(y0), x1 = std::round(x1), y1 = std::round(y1);
  cairo_device_to_user(cr, &x0, &y0);
  cairo_device_to_user(cr, &x1, &y1);
  cairo_new_path(cr);
  cairo_rectangle(cr, x0, y0, x1 - x0, y1 - y0);
  cairo_clip(cr);
}

}  // namespace vibra::render
