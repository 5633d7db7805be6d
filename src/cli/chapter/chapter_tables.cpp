// Finds a table's header in a command's output and reads or masks its cells by column.
#include "cli/chapter/chapter_tables.hpp"

#include <algorithm>
#include <sstream>

namespace vibra::cli {

namespace {
/// A word of a line and where it stands.
struct Word {
  std::string text;
  size_t begin, end;
};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<Word> words_of(const std::string& line, bool csv) {
  std::vector<Word> words;
  size_t at = 0;
  while (at < line.size()) {
    if (!csv) at = std::min(line.find_first_not_of(' ', at), line.size());
    if (at == line.size()) break;
    const size_t end = std::min(line.find(csv ? ',' : ' ', at), line.size());
    words.push_back({line.substr(at, end - at), at, end});
    at = end + (csv ? 1 : 0);
  }
  if (csv && !line.empty() && line.back() == ',') words.push_back({"", line.size(), line.size()});
  return words;
}

/// A table: its header's words and the lines of its rows.
struct Block {
  bool csv;
  std::vector<Word> header;
  size_t first_row, end_row;
};

/// Whether `line` is a row under `header`: as many cells (CSV), or every word
/// standing under a header word (aligned), so a sentence under a table is not one.
bool fits(bool csv, const std::vector<Word>& header, const std::string& line) {
  const std::vector<Word> words = words_of(line, csv);
  if (csv) return words.size() == header.size();
  for (const Word& word : words) {
    const bool under = std::any_of(header.begin(), header.end(),
                                   [&](const Word& head) { return word.end == head.end || word.begin == head.begin; });
    if (!under) return false;
  }
  return !words.empty();
}

/// Every line followed by lines that fit under it, as a table.
std::vector<Block> blocks_of(const std::vector<std::string>& lines) {
  std::vector<Block> blocks;
  for (size_t i = 0; i + 1 < lines.size(); ++i) {
    const bool csv = lines[i].find(',') != std::string::npos && lines[i].find(' ') == std::string::npos;
    const std::vector<Word> header = words_of(lines[i], csv);
    size_t end = i + 1;
    while (end < lines.size() && fits(csv, header, lines[end])) ++end;
    if (end == i + 1) continue;
    blocks.push_back({csv, header, i + 1, end});
    if (csv) i = end - 1;  // a CSV row is no header: one pass over a long CSV, not one per row
  }
  return blocks;
}

/// The index of the header word named `name`, or npos.
size_t column_index(const Block& block, const std::string& name) {
  for (size_t i = 0; i < block.header.size(); ++i)
    if (block.header[i].text == name) return i;
  return std::string::npos;
}

/// The word of `line` under header word `column`; nullptr for an empty cell.
const Word* cell_word(const Block& block, const std::vector<Word>& words, size_t column) {
  if (block.csv) return column < words.size() ? &words[column] : nullptr;
  const Word& head = block.header[column];
  for (const Word& word : words)
    if (word.end == head.end || word.begin == head.begin) return &word;  // numbers right-aligned, text left
  return nullptr;
}

std::string cell_text(const Block& block, const std::string& line, size_t column) {
  const std::vector<Word> words = words_of(line, block.csv);
  const Word* word = cell_word(block, words, column);
  return word ? word->text : "";
}

bool row_matches(const Block& block, const std::string& line,
                 const std::vector<std::pair<std::string, std::string>>& row) {
  for (const auto& [column, value] : row)
    if (value != "last" && cell_text(block, line, column_index(block, column)) != value) return false;
  return true;
}
}  // namespace

std::string table_cell(const std::string& text, const std::string& column,
                       const std::vector<std::pair<std::string, std::string>>& row) {
  const std::vector<std::string> lines = lines_of(text);
  for (const Block& block : blocks_of(lines)) {
    bool has_all = column_index(block, column) != std::string::npos;
    for (const auto& cell : row) has_all = has_all && column_index(block, cell.first) != std::string::npos;
    if (!has_all) continue;
    std::string found;
    for (size_t i = block.first_row; i < block.end_row; ++i)
      if (row_matches(block, lines[i], row)) found = cell_text(block, lines[i], column_index(block, column));
    return found;
  }
  return "";
}

std::string mask_columns(const std::string& text, const std::vector<std::string>& columns) {
  std::vector<std::string> lines = lines_of(text);
  for (const Block& block : blocks_of(lines))
    for (const std::string& name : columns) {
      const size_t column = column_index(block, name);
      if (column == std::string::npos) continue;
      for (size_t i = block.first_row; i < block.end_row; ++i) {
        const std::vector<Word> words = words_of(lines[i], block.csv);
        const Word* word = cell_word(block, words, column);
        if (!word) continue;
        const std::string dash = block.csv ? "-" : std::string(word->end - word->begin - 1, ' ') + "-";
        lines[i].replace(word->begin, word->end - word->begin, dash);
      }
    }
  std::string out;
  for (const std::string& line : lines) out += line + '\n';
  return out;
}

}  // namespace vibra::cli
