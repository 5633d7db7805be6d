#pragma once
#include <functional>
#include <optional>

#include "render/canvas.hpp"

namespace vibra::scenes {

/// The parts of a frame that never change (background, fixed axes, faint
/// whole-run curves), drawn once into an image and painted under each raster
/// frame; vector canvases (SVG, PDF) get them drawn directly. What becomes
/// permanent as time goes on (a curve drawn up to now) is added to the image
/// by `grow(layer, from_start)`, one frame's worth at a time, instead of being
/// stroked again from t = 0 on every frame.
class StaticLayer {
 public:
  using Grow = std::function<void(render::Canvas& layer, bool from_start)>;
  explicit StaticLayer(std::function<void(render::Canvas&)> draw) : draw_(std::move(draw)) {}

  void paint(render::Canvas& canvas, const Grow& grow = {}) {
    if (cairo_surface_get_type(canvas.surface()) != CAIRO_SURFACE_TYPE_IMAGE) {
      draw_(canvas);
      if (grow) grow(canvas, true);
      return;
    }
    const bool fresh = !cache_;
    if (fresh) {
      cache_.emplace(render::Canvas::image(canvas.width(), canvas.height()));
      draw_(*cache_);
    }
    if (grow) grow(*cache_, fresh);
    cache_->flush();
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
