// Table: results printed with aligned columns for people or as CSV for programs.
#pragma once
#include <string>
#include <variant>
#include <vector>

namespace vibra::app {

/// A table of results, printed with aligned columns for people or as CSV for
/// programs. Reals show 4 significant digits when aligned and the shortest
/// form that reads back exactly in CSV; NaN is an empty cell.
class Table {
 public:
  using Cell = std::variant<std::string, long long, double>;

  explicit Table(std::vector<std::string> columns) : columns_(std::move(columns)) {}
  void add_row(std::vector<Cell> cells) { rows_.push_back(std::move(cells)); }
  size_t rows() const { return rows_.size(); }
  const std::vector<std::string>& columns() const { return columns_; }
  const Cell& cell(size_t row, size_t column) const { return rows_[row][column]; }

  /// The table as lines, each ending in a newline.
  std::string aligned() const;
  std::string csv() const;

 private:
  std::vector<std::string> columns_;
  std::vector<std::vector<Cell>> rows_;
};

}  // namespace vibra::app
