#include "scenes/plot_scene.hpp"

#include "render/caption.hpp"

namespace vibra::scenes {

namespace {
std::vector<SeriesSpec> series_for(const SceneStyle& style, const std::string& quantity,
                                   const std::function<double(double)>& exact, const std::string& exact_label) {
  std::vector<SeriesSpec> series = {
      {"<i>" + quantity + "</i> numerical", style.colors.bob, [](std::span<const double> row) { return row[1]; }}};
  if (exact)
    series.push_back({"<i>" + quantity + "</i> " + exact_label, style.colors.gravity,
                      [exact](std::span<const double> row) { return exact(row[0]); }, true});
  return series;
}
}  // namespace

PlotScene::PlotScene(int width, int height, double t_end, SceneStyle style, const std::string& quantity,
                     std::function<double(double)> exact, const std::string& exact_label)
    : style_(std::move(style)),
      area_{0, 0, double(width), double(height)},
      panel_(render::PixelRect{0, 44 * render::scale_for_height(height), width - 10 * render::scale_for_height(height),
                               height - 74 * render::scale_for_height(height)},
             render::scale_for_height(height), "<i>" + quantity + "</i>", series_for(style_, quantity, exact, exact_label),
             t_end, style_.window_mode, style_.window),
      background_([this](render::Canvas& canvas) {
        canvas.clear(style_.colors.background);
        panel_.draw_static(canvas, true);
        if (!style_.caption.empty())  // one line under the time axis: shrunk, or cut short, to the width
          render::draw_caption(canvas, {16 * canvas.scale(), area_.h - 6 * canvas.scale()},
                               render::fit_caption(canvas, style_.caption, area_.w - 32 * canvas.scale(),
                                                   {15, style_.colors.wire.with_alpha(0.75)}, 1));
      }) {}

void PlotScene::prepare() {
  if (!prepared_) panel_.finish_recording(), prepared_ = true;
}

StaticLayer::Grow PlotScene::progress_to(double t) {
  return [this, t](render::Canvas& layer, bool from_start) { panel_.draw_progress(layer, t, from_start); };
}

void PlotScene::skip(const render::Canvas& canvas, std::span<const double> row) {
  prepare();
  background_.skip(canvas, progress_to(row[0]));
}

void PlotScene::draw(render::Canvas& canvas, std::span<const double> row) {
  prepare();
  background_.paint(canvas, progress_to(row[0]));
  panel_.draw(canvas, row[0], row, true);
  // The read-out sits top right: the panel's y label is top left.
  draw_readout(canvas, {area_.w * 0.55, 0, area_.w * 0.45, 40}, row[0], style_);
}

}  // namespace vibra::scenes
