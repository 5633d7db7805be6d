#pragma once
#include <functional>
#include <optional>

#include "render/canvas.hpp"

namespace vibra::scenes {

/// The parts of a frame that never change (background, fixed axes, faint
/// whole-run curves), drawn once into an image and painted under each raster
/// frame; vector canvases (SVG, PDF) get them drawn directly.
class StaticLayer {
 public:
  explicit StaticLayer(std::function<void(render::Canvas&)> draw) : draw_(std::move(draw)) {}

  void paint(render::Canvas& canvas) {
    if (cairo_surface_get_type(canvas.surface()) != CAIRO_SURFACE_TYPE_IMAGE) return draw_(canvas);
    if (!cache_) {
      cache_.emplace(render::Canvas::image(canvas.width(), canvas.height()));
      draw_(*cache_);
      cache_->flush();
    }
    cairo_t* cr = canvas.cr();
    cairo_save(cr);
    cairo_set_source_surface(cr, cache_->surface(), 0, 0);
    cairo_set_operator(cr, CAIRO_OPERATOR_SOURCE);
    cairo_paint(cr);
    cairo_restore(cr);
  }

 private:
  std::function<void(render::Canvas&)> draw_;
  std::optional<render::Canvas> cache_;
};

}  // namespace vibra::scenes
