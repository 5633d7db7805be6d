#include "render/column_envelope.hpp"

#include <algorithm>
#include <cmath>

namespace vibra::render {

ColumnEnvelope::ColumnEnvelope(int columns, double x0, double x1)
    : cells_(std::max(1, columns)), x0_(x0), x1_(x1 > x0 ? x1 : x0 + 1) {}

int ColumnEnvelope::column_of(double x) const {
  const double f = (x - x0_) / (x1_ - x0_);
  return std::clamp(static_cast<int>(std::floor(f * columns())), 0, columns() - 1);
}

int ColumnEnvelope::used_before(int column) const {
  for (int c = std::min(column, columns()) - 1; c >= 0; --c)
    if (cells_[c].used) return c;
  return -1;
}

void ColumnEnvelope::add(double x, double y) {
  if (!std::isfinite(y)) return;
  Cell& k = cells_[column_of(x)];
  if (!k.used) {
    k = {true, true, y, y, y, y};
    return;
  }
  k.last = y;
  if (y < k.min) k.min = y, k.min_first = false;
  if (y > k.max) k.max = y, k.min_first = true;
}

std::optional<std::pair<double, double>> ColumnEnvelope::extremes_in_order(int column) const {
  const Cell& k = cells_[column];
  if (!k.used) return std::nullopt;
  return k.min_first ? std::pair{k.min, k.max} : std::pair{k.max, k.min};
}

ColumnEnvelope ColumnEnvelope::coarsened(int factor) const {
  factor = std::max(1, factor);
  const int columns = (this->columns() + factor - 1) / factor;
  ColumnEnvelope out(columns, x0_, x0_ + (x1_ - x0_) * columns * factor / this->columns());
  for (int c = 0; c < this->columns(); ++c) {
    const Cell& k = cells_[c];
    if (!k.used) continue;
    Cell& m = out.cells_[c / factor];
    if (!m.used) {
      m = k;
      continue;
    }
    // Cells arrive in time order: a new extreme is the latest one.
    m.last = k.last;
    const double min_before = m.min, max_before = m.max;
    if (k.min < min_before) m.min = k.min, m.min_first = false;
    if (k.max > max_before) m.max = k.max, m.min_first = true;
    // Both extremes new: they keep the order they had inside k.
    if (k.min < min_before && k.max > max_before) m.min_first = k.min_first;
  }
  return out;
}

void ColumnEnvelope::clear() { std::fill(cells_.begin(), cells_.end(), Cell{}); }

}  // namespace vibra::render
