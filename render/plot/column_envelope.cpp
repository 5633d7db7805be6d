// ColumnEnvelope: a whole curve decimated to one min/max cell per pixel column.
#include "render/plot/column_envelope.hpp"

#include <algorithm>
#include <cmath>

namespace vibra::render {

ColumnEnvelope::ColumnEnvelope(int columns, double x0, double x1)
    : cells_(std::max(1, columns)), x0_(x0), x1_(x1 > x0 ? x1 : x0 + 1) {}

int ColumnEnvelope::column_of(double x) const {
  const double f = (x - x0_) / (x1_ - x0_);
  // Clamped before the cast: x far outside the range would overflow an int (and land in column 0).
  return static_cast<int>(std::clamp(std::floor(f * columns()), 0.0, columns() - 1.0));
}

int ColumnEnvelope::used_before(int column) const {
  for (int c = std::min(column, columns()) - 1; c >= 0; --c)
    if (cells_[c].used) return c;
  return -1;
}

void ColumnEnvelope::add(double x, double y) {
  if (std::isfinite(y)) cells_[column_of(x)].add(x, y);
}

std::optional<std::pair<double, double>> ColumnEnvelope::extremes_in_order(int column) const {
  const EnvelopeCell& k = cells_[column];
  if (!k.used) return std::nullopt;
  return k.min_first ? std::pair{k.min.y, k.max.y} : std::pair{k.max.y, k.min.y};
}

ColumnEnvelope ColumnEnvelope::coarsened(int factor) const {
  factor = std::max(1, factor);
  const int columns = (this->columns() + factor - 1) / factor;
  ColumnEnvelope out(columns, x0_, x0_ + (x1_ - x0_) * columns * factor / this->columns());
  // Cells arrive in time order, so each merges in as the later one.
  for (int c = 0; c < this->columns(); ++c) out.cells_[c / factor].merge_later(cells_[c]);
  return out;
}

void ColumnEnvelope::clear() { std::fill(cells_.begin(), cells_.end(), EnvelopeCell{}); }

}  // namespace vibra::render
