// The numbers the book prints for the chapter's figures and exercises, and where vibra prints its own.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace vibra::cli {

/// One number the book gives, and the cell of a command's table where vibra
/// prints the same quantity.
struct BookNumber {
  std::string item;    ///< "ex1.9": the item (chapter_items.hpp)
  size_t command;      ///< which of the item's commands prints it, from 0
  std::string column;  ///< the table column that holds vibra's value
  /// COLUMN=VALUE cells that pick the row, as printed; VALUE "last": the last row that matches the others.
  std::vector<std::pair<std::string, std::string>> row;
  std::string book;       ///< the book's value, as printed there
  double tolerance;       ///< relative: agree when |vibra - book| <= tolerance |book|
  std::string note = "";  ///< why a known difference is larger than the digits printed
};

/// "r scheme=centered i=last": the quantity, as --book-values and the page name it.
std::string quantity_name(const BookNumber&);

/// The stored book values, in the chapter's order.
const std::vector<BookNumber>& book_numbers();

/// The stored values with some replaced from a CSV file of lines
/// `ITEM,QUANTITY,VALUE` (# starts a comment), e.g.
/// `ex1.9,max_rel_energy_error scheme=rk4 T=10 dt=0.05,3.510e-2`. Throws
/// UsageError naming a line that is not one, or a quantity that is unknown.
std::vector<BookNumber> book_numbers_with(const std::string& file);

}  // namespace vibra::cli
