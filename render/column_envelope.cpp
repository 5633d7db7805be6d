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

void ColumnEnvelope::add(double x, double y) {
  if (!std::isfinite(y)) return;
  Cell& k = cells_[column_of(x)];
  if (!k.used) {
    k = {true, y, y, y, y};
    return;
  }
  k.last = y;
  k.min = std::min(k.min, y);
  k.max = std::max(k.max, y);
}

void ColumnEnvelope::clear() { std::fill(cells_.begin(), cells_.end(), Cell{}); }

}  // namespace vibra::render
