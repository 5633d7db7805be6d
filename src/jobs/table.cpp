// Table: results printed with aligned columns for people or as CSV for programs.
#include "jobs/table.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace vibra::app {

namespace {
std::string aligned_text(const Table::Cell& cell) {
  if (const auto* text = std::get_if<std::string>(&cell)) return *text;
  if (const auto* integer = std::get_if<long long>(&cell)) return std::to_string(*integer);
  const double x = std::get<double>(cell);
  if (std::isnan(x)) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

std::string csv_text(const Table::Cell& cell) {
  if (const auto* real = std::get_if<double>(&cell)) {
    if (std::isnan(*real)) return "";
    char buf[32];
    return std::string(buf, std::to_chars(buf, buf + sizeof buf, *real).ptr);
  }
  return aligned_text(cell);
}
}  // namespace

std::string Table::aligned() const {
  std::string out;
  std::vector<size_t> widths;
  for (const auto& c : columns_) widths.push_back(c.size());
  for (const auto& row : rows_)
    for (size_t i = 0; i < row.size() && i < widths.size(); ++i) widths[i] = std::max(widths[i], aligned_text(row[i]).size());
  auto add_line = [&](const std::vector<std::string>& cells, const std::vector<bool>& left) {
    std::string line;
    for (size_t i = 0; i < cells.size(); ++i) {
      const std::string pad(widths[i] - cells[i].size(), ' ');
      line += (i ? "  " : "") + (left[i] ? cells[i] + pad : pad + cells[i]);
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out += line + '\n';
  };
  // Text columns align left, numbers right; headers follow their column.
  std::vector<bool> left(columns_.size(), false);
  if (!rows_.empty())
    for (size_t i = 0; i < columns_.size() && i < rows_[0].size(); ++i) left[i] = std::holds_alternative<std::string>(rows_[0][i]);
  add_line(columns_, left);
  for (const auto& row : rows_) {
    std::vector<std::string> cells;
    for (const auto& cell : row) cells.push_back(aligned_text(cell));
    add_line(cells, left);
  }
  return out;
}

std::string Table::csv() const {
  std::string out;
  auto add_line = [&](const std::vector<std::string>& cells) {
    for (size_t i = 0; i < cells.size(); ++i) out += (i ? "," : "") + cells[i];
    out += '\n';
  };
  add_line(columns_);
  for (const auto& row : rows_) {
    std::vector<std::string> cells;
    for (const auto& cell : row) cells.push_back(csv_text(cell));
    add_line(cells);
  }
  return out;
}

}  // namespace vibra::app
