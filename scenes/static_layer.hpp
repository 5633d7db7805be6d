// The parts of a frame that never change, drawn once into an image and painted under each frame.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>

#include "render/draw/canvas.hpp"

namespace vibra::scenes {

/// The parts of a frame that never change (background, fixed axes), drawn once into an image and painted under each raster
/// frame; vector canvases (SVG, PDF) get them drawn directly. What becomes
/// permanent as time goes on (a curve drawn up to now) is added to the image
/// by `grow(growth)`, one frame's worth at a time, instead of being stroked
/// again from t = 0 on every frame.

/// What a frame may add to the layer under it: the layer, whether it is new
/// (everything up to now is drawn from the start), and a way to put the
/// static drawing back in a strip, so that the end of a curve can be drawn
/// again as one stroke of the whole curve would draw it.
class LayerGrowth {
 public:
  LayerGrowth(render::Canvas& layer, bool from_start, const render::Canvas* pristine)
      : layer(layer), from_start(from_start), pristine_(pristine) {}
  render::Canvas& layer;
  const bool from_start;
  /// Restores the static drawing inside `strip` (whole pixels); never
  /// needed when from_start.
  void reset(const render::PixelRect& strip) {
    if (!pristine_ || strip.w <= 0 || strip.h <= 0) return;
    cairo_t* cr = layer.cr();
    cairo_save(cr);
    cairo_rectangle(cr, strip.x, strip.y, strip.w, strip.h);
    cairo_clip(cr);
    layer.mark_drawn(strip.x, strip.y, strip.x + strip.w, strip.y + strip.h);
    cairo_set_source_surface(cr, pristine_->surface(), 0, 0);
    cairo_set_operator(cr, CAIRO_OPERATOR_SOURCE);
    cairo_paint(cr);
    cairo_restore(cr);
  }

 private:
  const render::Canvas* pristine_;
};

class StaticLayer {
 public:
  using Grow = std::function<void(LayerGrowth&)>;
  explicit StaticLayer(std::function<void(render::Canvas&)> draw) : draw_(std::move(draw)) {}

  /// Paints the layer under a frame. On a canvas that tracks damage, only
  /// where the last frame drew, and where the layer grew, is repainted: the
  /// rest of the canvas already shows the layer.
  void paint(render::Canvas& canvas, const Grow& grow = {}) {
    if (cairo_surface_get_type(canvas.surface()) != CAIRO_SURFACE_TYPE_IMAGE) {
      draw_(canvas);
      LayerGrowth growth(canvas, true, nullptr);
      if (grow) grow(growth);
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
      if (grow) {  // the static drawing alone, for LayerGrowth::reset
        pristine_.emplace(render::Canvas::image(canvas.width(), canvas.height()));
        cache_->flush();
        cairo_set_source_surface(pristine_->cr(), cache_->surface(), 0, 0);
        cairo_set_operator(pristine_->cr(), CAIRO_OPERATOR_SOURCE);
        cairo_paint(pristine_->cr());
        pristine_->flush();
      }
    }
    cache_->begin_frame();
    LayerGrowth growth(*cache_, fresh, pristine_ ? &*pristine_ : nullptr);
    if (grow) grow(growth);
    cache_->flush();
    return fresh;
  }

  std::function<void(render::Canvas&)> draw_;
  std::optional<render::Canvas> cache_;
  std::optional<render::Canvas> pristine_;  ///< the layer before anything grew on it
  std::uint64_t painted_on_ = 0;  ///< Canvas::id of the canvas painted last: only it holds the layer already
};

}  // namespace vibra::scenes
