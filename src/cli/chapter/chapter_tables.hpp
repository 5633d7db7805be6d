// Reading the tables a vibra command prints (aligned or CSV) back into cells, to compare and to mask.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace vibra::cli {

/// The cell of `column` in the row that `row`'s COLUMN=VALUE pairs pick
/// (VALUE "last": the last row matching the others), from the first table in
/// `text` whose header holds all those columns; "" when there is none. Reads
/// aligned tables (numbers end under their header, text starts under it) and
/// CSV.
std::string table_cell(const std::string& text, const std::string& column,
                       const std::vector<std::pair<std::string, std::string>>& row);

/// `text` with every cell of a column named in `columns` replaced by "-"
/// (timings, which differ from run to run), in aligned tables and CSV.
std::string mask_columns(const std::string& text, const std::vector<std::string>& columns);

}  // namespace vibra::cli
