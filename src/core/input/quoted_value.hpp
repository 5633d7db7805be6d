// A user's value fit to quote in a one-line message: control characters escaped, long text cut.
#pragma once
#include <string>
#include <string_view>

namespace vibra {

/// A value the user typed, fit to quote in a one-line message: control
/// characters (a newline in a value) shown as escapes, and anything over
/// `limit` characters cut in the middle with "..." and its length, so a
/// 10 MB expression or a 300-digit number never floods the terminal.
std::string quoted_value(std::string_view text, std::size_t limit = 40);

/// A number for a message: %.6g, so 1e308 is "1e+308", never 309 digits.
std::string short_number(double value);

/// One line of at most `limit` characters: control characters escaped, the
/// middle of an overlong message cut (the start names the problem, the end
/// the fix). The last guard before an error reaches the terminal.
std::string one_line_message(std::string_view message, std::size_t limit = 240);

}  // namespace vibra
