#include "app/table.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

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

void Table::print_aligned(std::FILE* out) const {
  std::vector<size_t> widths;
  for (const auto& c : columns_) widths.push_back(c.size());
  for (const auto& row : rows_)
    for (size_t i = 0; i < row.size() && i < widths.size(); ++i) widths[i] = std::max(widths[i], aligned_text(row[i]).size());
  auto print_line = [&](const std::vector<std::string>& cells, const std::vector<bool>& left) {
    std::string line;
    for (size_t i = 0; i < cells.size(); ++i) {
      const std::string pad(widths[i] - cells[i].size(), ' ');
      line += (i ? "  " : "") + (left[i] ? cells[i] + pad : pad + cells[i]);
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    std::fprintf(out, "%s\n", line.c_str());
  };
  // Text columns align left, numbers right; headers follow their column.
  std::vector<bool> left(columns_.size(), false);
  if (!rows_.empty())
    for (size_t i = 0; i < columns_.size() && i < rows_[0].size(); ++i) left[i] = std::holds_alternative<std::string>(rows_[0][i]);
  print_line(columns_, left);
  for (const auto& row : rows_) {
    std::vector<std::string> cells;
    for (const auto& cell : row) cells.push_back(aligned_text(cell));
    print_line(cells, left);
  }
}

void Table::print_csv(std::FILE* out) const {
  auto print_line = [&](const std::vector<std::string>& cells) {
    std::string line;
    for (size_t i = 0; i < cells.size(); ++i) line += (i ? "," : "") + cells[i];
    std::fprintf(out, "%s\n", line.c_str());
  };
  print_line(columns_);
  for (const auto& row : rows_) {
    std::vector<std::string> cells;
    for (const auto& cell : row) cells.push_back(csv_text(cell));
    print_line(cells);
  }
}

}  // namespace vibra::app
