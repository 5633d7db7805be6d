// Colour: RGBA values, parsing "#rrggbb", and a palette that reads well projected (Okabe-Ito).
#pragma once
#include <cstddef>
#include <string>

namespace vibra::render {

/// An RGBA colour with components in [0, 1].
struct Color {
  double r = 0, g = 0, b = 0, a = 1;
  Color with_alpha(double alpha) const { return {r, g, b, alpha}; }
  bool operator==(const Color&) const = default;
};

/// Parses "#rrggbb" or "#rrggbbaa"; throws std::invalid_argument otherwise.
Color parse_color(const std::string& hex);

/// A palette that reads well projected in a lecture hall and in print
/// (Okabe-Ito colours, distinguishable with colour-blindness).
namespace palette {
inline constexpr Color ink{0.10, 0.10, 0.12};
inline constexpr Color grid{0.88, 0.88, 0.90};
inline constexpr Color faint{0.72, 0.72, 0.75};
inline constexpr Color paper{1, 1, 1};
inline constexpr Color blue{0.00, 0.45, 0.70};
inline constexpr Color vermillion{0.84, 0.37, 0.00};
inline constexpr Color green{0.00, 0.62, 0.45};
inline constexpr Color purple{0.80, 0.47, 0.65};
inline constexpr Color orange{0.90, 0.62, 0.00};
inline constexpr Color sky{0.34, 0.71, 0.91};
inline constexpr Color yellow{0.94, 0.89, 0.26};
/// Forces in a comparison, where the hues name runs.
inline constexpr Color charcoal{0.30, 0.30, 0.34};

/// The k-th of eight colours for curves that must be told apart (runs of a
/// comparison, schemes of a study): Okabe-Ito, the most legible first.
Color series(size_t k);
}  // namespace palette

}  // namespace vibra::render
