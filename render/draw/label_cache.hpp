// LabelCache: labels of an image canvas laid out once and kept as images, pasted on later frames.
#pragma once
#include <cairo.h>
#include <pango/pango.h>

#include <cstddef>
#include <memory>
#include <string>
#include <unordered_map>

namespace vibra::render {

/// Labels of an image canvas, laid out once and drawn once. Most labels of an
/// animation repeat every frame (an arrow's "−ku", a legend, a read-out's
/// words), and setting one costs far more than copying its pixels: Pango
/// parses and shapes the markup, and a halo strokes every glyph's outline.
/// A label is kept as its extents and, once drawn, as a small premultiplied
/// image whose origin sits at whole pixels, so pasting it at a whole-pixel
/// point gives the pixels drawing it there would (up to the rounding of a
/// two-step composite, a level or so). Every label goes through its image,
/// even one drawn once only (the time's digits): a frame's pixels must not
/// depend on which frames came before it (a segment starts anywhere).
///
/// When the kept labels pass a count or their images a byte budget, the cache
/// starts afresh, so memory stays bounded over any run.
class LabelCache {
 public:
  struct Label {
    PangoRectangle ink{}, logical{};  ///< pixels, relative to the layout's origin
    std::shared_ptr<PangoLayout> layout;     ///< from measuring, until drawn
    std::shared_ptr<cairo_surface_t> image;  ///< once drawn: halo and text
    int x = 0, y = 0;                        ///< the image's top-left from the layout's origin
  };

  explicit LabelCache(std::size_t byte_budget, std::size_t most_labels = 2048)
      : budget_(byte_budget), most_labels_(most_labels) {}

  /// The label kept under `key` (everything that decides its pixels), or null.
  Label* find(const std::string& key);
  /// Keeps a new label under `key`; over the budget, forgets the others first.
  Label& keep(const std::string& key, Label label);
  /// Notes the bytes of an image just given to a kept label.
  void count_image(std::size_t bytes) { used_ += bytes; }

  std::size_t size() const { return labels_.size(); }

 private:
  std::size_t budget_, most_labels_, used_ = 0;
  std::unordered_map<std::string, Label> labels_;
};

}  // namespace vibra::render
