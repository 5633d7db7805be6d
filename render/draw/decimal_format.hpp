// Writes a number with one decimal exactly as printf("%.1f") would, without printf's cost.
#pragma once

namespace vibra::render {

/// Writes x with one decimal exactly as printf("%.1f") would, without
/// printf's cost (the ASCII plotter writes one per line, millions per second).
/// `out` needs room for 320 characters (%.1f of 1e308 is 310). Returns the end
/// of the text.
char* format_one_decimal(char* out, double x);

}  // namespace vibra::render
