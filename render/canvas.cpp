#include "render/canvas.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>

#include <string>

#include "render/output_error.hpp"

namespace vibra::render {

namespace {
constexpr int kMaxSide = 8192;

void check_size(int width, int height) {
  if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide)
    throw OutputError("size " + std::to_string(width) + "x" + std::to_string(height) +
                      " is out of range: width and height must be 1..8192, e.g. --size 1280x720");
}
}  // namespace

Canvas::Canvas(cairo_surface_t* surface, int width, int height)
    : surface_(surface, cairo_surface_destroy), width_(width), height_(height) {
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS)
    throw OutputError(std::string("cannot create the drawing surface: ") +
                      cairo_status_to_string(cairo_surface_status(surface)));
  cr_.reset(cairo_create(surface), cairo_destroy);
  cairo_set_antialias(cr_.get(), CAIRO_ANTIALIAS_GOOD);
  cairo_set_line_join(cr_.get(), CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr_.get(), CAIRO_LINE_CAP_ROUND);
}

Canvas Canvas::image(int width, int height) {
  check_size(width, height);
  return Canvas(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height), width, height);
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
  cairo_save(cr());
  cairo_set_source_rgba(cr(), c.r, c.g, c.b, c.a);
  cairo_set_operator(cr(), CAIRO_OPERATOR_SOURCE);
  cairo_paint(cr());
  cairo_restore(cr());
}

WorldView::WorldView(const Eigen::AlignedBox2d& world, const PixelRect& pixels) {
  const Point size = world.sizes();
  zoom_ = std::min(pixels.w / size.x(), pixels.h / size.y());
  const Point c = world.center(), p = pixels.center();
  // x' = p.x + zoom (x - c.x), y' = p.y - zoom (y - c.y): y flips to point down.
  transform_.matrix() << zoom_, 0, p.x() - zoom_ * c.x(), 0, -zoom_, p.y() + zoom_ * c.y(), 0, 0, 1;
}

}  // namespace vibra::render
