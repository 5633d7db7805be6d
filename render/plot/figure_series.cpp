// A figure's series (points, curve or path, decimated as they stream) and how each is drawn.
#include "render/plot/figure_series.hpp"

namespace vibra::render {

Series::Series(Kind kind, std::string label, SeriesStyle style, int columns, double x0, double x1)
    : kind_(kind), label_(std::move(label)), style_(style), columns_(std::max(1, columns)), x0_(x0), x1_(x1) {
  if (kind_ == Kind::path) path_.emplace();
}

void Series::add(double x, double y) {
  ++count_;
  if (path_) return path_->add(x, y);
  if (envelope_) return envelope_->add(x, y);
  points_.emplace_back(x, y);
  if (kind_ == Kind::curve && static_cast<long long>(points_.size()) > columns_) {
    envelope_.emplace(columns_, x0_, x1_);
    for (const Point& p : points_) envelope_->add(p.x(), p.y());
    std::vector<Point>().swap(points_);  // release the memory, not just the size
  }
}

std::vector<std::vector<Point>> Series::polylines() const {
  if (path_) return path_->strokes();
  if (!envelope_) return {points_};
  return {envelope_->polyline(0, envelope_->columns() - 1, [](double x, double y) { return Point(x, y); })};
}

void Series::for_each_point(const std::function<void(double, double)>& visit) const {
  if (path_) {
    for (const auto& stroke : path_->strokes())
      for (const Point& p : stroke) visit(p.x(), p.y());
    return;
  }
  for (const auto& line : polylines())
    for (const Point& p : line) visit(p.x(), p.y());
}

}  // namespace vibra::render
