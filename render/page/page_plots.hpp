// A lecture page's plots: curves decimated to min/max envelopes and packed into the page.
#pragma once
#include <string>
#include <vector>

#include "render/draw/color.hpp"
#include "render/plot/column_envelope.hpp"

namespace vibra::render {

/// One curve of a page's plots, streamed in sample by sample on the mesh
/// t_n = t0 + n dt. It keeps a min/max envelope of many columns over
/// [t0, t_end] (coarsened into a pyramid of zoom levels when the page is
/// written) and, while they are few, the samples themselves. Memory is
/// bounded whatever the run's length.
class PageSeriesData {
 public:
  /// Finest envelope: at most this many columns over the run.
  static constexpr int kMaxColumns = 2048 * 64;
  /// Samples kept exactly up to this count (beyond it only the envelope).
  static constexpr long long kMaxExactSamples = 1 << 18;

  /// `samples`: how many samples the run will give (sizes the envelope).
  PageSeriesData(double t0, double t_end, double dt, long long samples);

  void add(double y);

  double t0() const { return t0_; }
  double dt() const { return dt_; }
  long long samples() const { return count_; }
  double t_end() const { return envelope_.x1(); }
  /// The finest envelope: 2048 times a power of 4 columns, just enough to
  /// stop decimating (about two samples a column), at most kMaxColumns.
  const ColumnEnvelope& envelope() const { return envelope_; }
  /// Every sample, or empty when there were more than kMaxExactSamples.
  const std::vector<float>& exact() const { return exact_; }
  bool has_exact() const { return count_ > 0 && count_ <= kMaxExactSamples; }
  /// Smallest and largest finite value seen (lo > hi when none).
  double lo() const { return lo_; }
  double hi() const { return hi_; }

 private:
  double t0_, dt_;
  ColumnEnvelope envelope_;
  std::vector<float> exact_;
  long long count_ = 0;
  double lo_ = 1e300, hi_ = -1e300;
};

/// A curve with its looks. `key` groups curves across panels for the page's
/// legend (a run's name, or "exact"): toggling a key shows or hides them all.
struct PageSeries {
  std::string label;
  std::string key;
  Color color;
  bool dashed = false;
  PageSeriesData data;
};

/// A panel of curves against time; all panels of a page share the time axis.
struct PagePanel {
  std::string label;  ///< plain text (Unicode), e.g. "θ (degrees)"
  std::vector<PageSeries> series;
};

/// The panels as the JSON object the page script reads:
///   {"t0":..,"t1":..,"panels":[{"label":..,"series":[{"label","key","color","dash","lo","hi",
///     "levels":[{"cells":C,"data":B64},...], "exact":{"t0","dt","count","data":B64} or null}]}]}
/// Each level holds, for each of its C cells over [t0, t1], the cell's two
/// extremes in the order they occurred, as 16-bit steps of [lo, hi]
/// (65535 = empty cell); levels grow 4x finer. `exact` holds every sample the
/// same way. Levels are chosen so the base64 text stays within
/// `budget_bytes` in all (the coarsest level shrinks if it must): a page's
/// size does not grow with the run's length.
std::string page_plots_json(const std::vector<PagePanel>&, size_t budget_bytes);

/// The budget lecture pages use: 1.5 MB of data (the page stays under 2 MB).
inline constexpr size_t kPagePlotBudgetBytes = 1'500'000;

}  // namespace vibra::render
