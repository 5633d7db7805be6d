#pragma once
#include <cstdint>
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

  /// Paints the layer under a frame. On a canvas that tracks damage, only
  /// where the last frame drew, and where the layer grew, is repainted: the
  /// rest of the canvas already shows the layer.
  void paint(render::Canvas& canvas, const Grow& grow = {}) {
    if (cairo_surface_get_type(canvas.surface()) != CAIRO_SURFACE_TYPE_IMAGE) {
      draw_(canvas);
      if (grow) grow(canvas, true);
      return;
    }
    const bool fresh = grow_for(canvas, grow);

    render::Damage region(canvas.width(), canvas.height());
    if (fresh || !canvas.tracks_damage() || painted_on_ != canvas.id()) {
      region.add_all();
    } else {
      region.add(canvas.drawn_last_frame());
      region.add(cache_->drawn());
    }
    painted_on_ = canvas.id();
    if (region.empty()) return;
    cairo_t* cr = canvas.cr();
    cairo_save(cr);
    if (!region.all()) {
      cairo_new_path(cr);
      for (const render::DamageRect& r : region.rects()) cairo_rectangle(cr, r.x0, r.y0, r.x1 - r.x0, r.y1 - r.y0);
      cairo_clip(cr);
    }
    cairo_set_source_surface(cr, cache_->surface(), 0, 0);
    cairo_set_operator(cr, CAIRO_OPERATOR_SOURCE);
    cairo_paint(cr);
    cairo_restore(cr);
    canvas.mark_restored(region);
  }

  /// For a frame that is not drawn (see Scene::skip): the layer grows as
  /// paint() would grow it under `canvas`, which is not touched.
  void skip(const render::Canvas& canvas, const Grow& grow) {
    if (cairo_surface_get_type(canvas.surface()) == CAIRO_SURFACE_TYPE_IMAGE) grow_for(canvas, grow);
  }

 private:
  /// Makes the layer for frames like `canvas`'s if need be, then grows it by
  /// one frame's worth; returns whether the layer was new.
  bool grow_for(const render::Canvas& canvas, const Grow& grow) {
    const bool fresh = !cache_;
    if (fresh) {
      cache_.emplace(render::Canvas::image(canvas.width(), canvas.height()));
      if (canvas.tracks_damage()) cache_->track_damage();
      draw_(*cache_);
    }
    cache_->begin_frame();
    if (grow) grow(*cache_, fresh);
    cache_->flush();
    return fresh;
  }

  std::function<void(render::Canvas&)> draw_;
  std::optional<render::Canvas> cache_;
  std::uint64_t painted_on_ = 0;  ///< Canvas::id of the canvas painted last: only it holds the layer already
};

}  // namespace vibra::scenes
