// RollingEnvelope: the latest stretch of a curve in one min/max cell per pixel column, in a ring of bounded size.
#include "render/plot/rolling_envelope.hpp"

#include <algorithm>
#include <cmath>

namespace vibra::render {

RollingEnvelope::RollingEnvelope(double column_width, int capacity)
    : width_(column_width > 0 ? column_width : 1), cells_(std::max(2, capacity)) {}

long long RollingEnvelope::column_of(double x) const {
  // Clamped before the cast: a double beyond long long's range is undefined
  // behaviour there (a huge x over a tiny column width).
  return static_cast<long long>(std::clamp(std::floor(x / width_), -9e18, 9e18));
}

void RollingEnvelope::add(double x, double y) {
  if (!std::isfinite(y) || x < 0) return;
  const long long c = column_of(x);
  newest_ = std::max(newest_, c);
  Column& k = cells_[slot(c)];
  if (k.column != c) k = {c, {}};  // a new column reuses the oldest slot
  k.cell.add(x, y);
}

}  // namespace vibra::render
