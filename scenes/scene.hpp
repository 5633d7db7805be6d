// Scene: a picture of a solution at one instant, fed solution rows (record, observe, draw).
#pragma once
#include <span>
#include <vector>

#include "render/draw/canvas.hpp"
#include "render/labels/drawing_record.hpp"

namespace vibra::scenes {

/// A picture of a solution at one instant, fed solution rows (t first, then
/// the model's columns). The render job calls record() for every step of a
/// pre-pass (fixed ranges over the run), then, while rendering, observe() for
/// every solver step and draw() for each frame. A segment of a render calls
/// skip() for each frame before its first, so that what its frames draw is
/// what the whole render draws for them.
class Scene {
 public:
  virtual ~Scene() = default;
  virtual void record(std::span<const double> row) = 0;
  virtual void observe(std::span<const double> row) = 0;
  /// Rows interpolated between coarse steps (see HistoryFeed): for curves
  /// and bounds only, never for sums over steps (work, dissipation).
  virtual void record_between(std::span<const double> row) { (void)row; }
  virtual void observe_between(std::span<const double> row) { (void)row; }
  /// The time between rows that the scene's curves resolve (a pixel
  /// column's worth, halved); 0 when solver steps are enough.
  virtual double sample_interval() const { return 0; }
  /// Before draw() or skip() of a frame: the next sample of each run that is
  /// straight between its samples (Trajectory::straight_samples_ahead), so
  /// that a quantity of the rows is drawn on the line between its values at
  /// the samples around the frame, where its curve runs (SampleBracket).
  virtual void look_ahead(std::span<const std::vector<double>> next_samples) { (void)next_samples; }
  virtual void draw(render::Canvas&, std::span<const double> row) = 0;
  /// A frame not drawn: keeps up what drawing it would have changed for the
  /// frames after it (the whole-run curves drawn so far), without drawing on
  /// `canvas`, which only says the frames' size and kind.
  virtual void skip(const render::Canvas&, std::span<const double> row) = 0;
  /// What the last drawn frame's diagram part covers and where its labels
  /// went (for checks of the layout); null for a scene without a diagram.
  virtual const render::DrawingRecord* last_layout() const { return nullptr; }
  /// Labels keep their spots from one drawn frame to the next within a chain
  /// of frames (render::LabelMemory); a frame of another chain forgets them.
  /// The render job numbers the chains, so that a still or a segment replays
  /// the frames of its chain before it and draws what the whole render draws.
  virtual void set_label_chain(long long chain) { (void)chain; }
};

}  // namespace vibra::scenes
