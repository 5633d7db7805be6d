// The typesetter for the LaTeX subset (render/typeset/): boxes whose
// geometry is known in advance, the ink inside the reported boxes, and one
// line naming the problem and the fix for bad input.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/models/model.hpp"
#include "core/scheme.hpp"
#include "render/labels/drawing_record.hpp"
#include "render/typeset/formula_draw.hpp"
#include "render/typeset/formula_layout.hpp"
#include "render/typeset/formula_parser.hpp"

using namespace vibra;
using namespace vibra::render;
using Role = MathBox::Role;

namespace {

MathBox set(const std::string& source, double size = 30, int height = 720) {
  Canvas canvas = Canvas::image(16, height);
  return layout_formula(canvas, parse_formula(source), {size});
}

/// The first box of `role` in the tree (depth first), with its origin.
const MathBox* find(const MathBox& box, Role role, Point origin, Point* found_at) {
  if (box.role == role) {
    *found_at = origin;
    return &box;
  }
  for (const MathBox& child : box.children)
    if (const MathBox* hit = find(child, role, origin + child.at, found_at)) return hit;
  return nullptr;
}

const MathBox& child_of(const MathBox& box, Role role) {
  for (const MathBox& child : box.children)
    if (child.role == role) return child;
  FAIL("no child of that role");
  return box;
}

std::vector<std::string> leaf_texts(const MathBox& box) {
  std::vector<std::string> texts;
  for_each_leaf(box, {0, 0}, [&](const MathBox& leaf, const Point&) {
    if (leaf.role == Role::glyphs) texts.push_back(leaf.text);
  });
  return texts;
}

std::vector<const MathBox*> glyph_leaves(const MathBox& box) {
  std::vector<const MathBox*> leaves;
  std::function<void(const MathBox&)> walk = [&](const MathBox& b) {
    if (b.role == Role::glyphs) leaves.push_back(&b);
    for (const MathBox& c : b.children) walk(c);
  };
  walk(box);
  return leaves;
}

std::string error_of(const std::function<void()>& body) {
  try {
    body();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "(no error)";
}

/// Draws `box` on a white picture and returns the bounding box of every
/// pixel that is not white (x0, y0, x1, y1 exclusive); empty: x0 > x1.
InkBox drawn_pixels(Canvas& canvas) {
  canvas.flush();
  InkBox ink;
  for (int y = 0; y < canvas.height(); ++y) {
    const auto* row = reinterpret_cast<const std::uint32_t*>(canvas.data() + std::size_t(y) * canvas.stride());
    for (int x = 0; x < canvas.width(); ++x)
      if (row[x] != 0xffffffffu) ink.add({double(x), double(y), x + 1.0, y + 1.0});
  }
  return ink;
}

}  // namespace

TEST_CASE("Greek letters map to their code points, lowercase italic and capitals upright", "[typeset]") {
  const MathBox box = set(R"(\alpha\beta\gamma\delta\theta\lambda\mu\pi\omega\Delta\Theta\Omega)");
  const std::vector<std::string> expected = {"α", "β", "γ", "δ", "θ", "λ", "μ", "π", "ω", "Δ", "Θ", "Ω"};
  CHECK(leaf_texts(box) == expected);
  const auto leaves = glyph_leaves(box);
  REQUIRE(leaves.size() == 12);
  CHECK(leaves[0]->font == MathFont::italic);   // α
  CHECK(leaves[8]->font == MathFont::italic);   // ω
  CHECK(leaves[9]->font == MathFont::upright);  // Δ
  CHECK(leaves[11]->font == MathFont::upright); // Ω
  // The code points themselves, not only the strings above.
  CHECK(std::string("α") == "\xce\xb1");  // U+03B1
  CHECK(std::string("Ω") == "\xce\xa9");  // U+03A9
  CHECK(std::string("θ") == "\xce\xb8");  // U+03B8
}

TEST_CASE("variables are italic, digits, function names and text upright, the minus U+2212", "[typeset]") {
  const MathBox box = set(R"(2x - \sin\theta + \text{at rest})");  // the leaves point into it
  const auto leaves = glyph_leaves(box);
  REQUIRE(leaves.size() == 7);
  CHECK(leaves[0]->text == "2");
  CHECK(leaves[0]->font == MathFont::upright);
  CHECK(leaves[1]->text == "x");
  CHECK(leaves[1]->font == MathFont::italic);
  CHECK(leaves[2]->text == "−");
  CHECK(leaves[3]->text == "sin");
  CHECK(leaves[3]->font == MathFont::upright);
  CHECK(leaves[4]->text == "θ");
  CHECK(leaves[6]->text == "at rest");  // spaces kept
  CHECK(leaves[6]->font == MathFont::text);
  // Primes: u'' is u and a double prime.
  CHECK(leaf_texts(set("u''")) == std::vector<std::string>{"u", "″"});
}

TEST_CASE("a fraction's bar spans the wider part and both parts sit centred above and below it", "[typeset]") {
  for (const char* source : {R"(\frac{a + b + c}{2})", R"(\frac{1}{x + y + z})", R"(\frac{\Delta t}{2})"}) {
    INFO(source);
    Point at;
    const MathBox tree1 = set(source);
    const MathBox* fraction = find(tree1, Role::fraction, {0, 0}, &at);
    REQUIRE(fraction);
    const MathBox& num = child_of(*fraction, Role::numerator);
    const MathBox& den = child_of(*fraction, Role::denominator);
    const MathBox& bar = child_of(*fraction, Role::rule);
    const double wider = std::max(num.width, den.width);
    CHECK(bar.width >= wider);
    CHECK(bar.width <= wider + 0.25 * 30);  // a small overhang, no more
    const double bar_centre = bar.at.x() + 0.5 * bar.width;
    CHECK(num.at.x() + 0.5 * num.width == Approx(bar_centre).margin(0.01));
    CHECK(den.at.x() + 0.5 * den.width == Approx(bar_centre).margin(0.01));
    // The numerator's ink above the bar's top, the denominator's below its bottom.
    const double bar_top = bar.at.y() - bar.ascent, bar_bottom = bar.at.y();
    CHECK(num.at.y() + num.ink.y1 < bar_top);
    CHECK(den.at.y() + den.ink.y0 > bar_bottom);
    // The bar sits on the math axis: above the baseline, below the x-height.
    CHECK(bar_bottom < 0);
    CHECK(bar_top > -0.6 * 30);
    // The fraction's box holds all of it.
    CHECK(fraction->ascent >= -(num.at.y() + num.ink.y0) - 1e-9);
    CHECK(fraction->descent >= den.at.y() + den.ink.y1 - 1e-9);
  }
}

TEST_CASE("superscripts are raised above the baseline, subscripts lowered, and both keep apart", "[typeset]") {
  const double em = 30;
  Point at;
  const MathBox tree2 = set("u^2");
  const MathBox* up = find(tree2, Role::scripts, {0, 0}, &at);
  REQUIRE(up);
  const MathBox& sup = child_of(*up, Role::superscript);
  CHECK(-sup.at.y() >= 0.35 * em);                           // its baseline well above the base's
  CHECK(sup.at.y() + sup.ink.y1 < 0);                        // its ink wholly above the baseline
  CHECK(glyph_leaves(sup).front()->size < em);                 // smaller than the base
  CHECK(sup.at.x() >= child_of(*up, Role::base).width - 1e-9);  // to the right of the base

  const MathBox tree3 = set("u_n");
  const MathBox* down = find(tree3, Role::scripts, {0, 0}, &at);
  REQUIRE(down);
  const MathBox& sub = child_of(*down, Role::subscript);
  CHECK(sub.at.y() >= 0.1 * em);  // its baseline below the base's

  const MathBox tree4 = set("u^{n+1}_{i}");
  const MathBox* both = find(tree4, Role::scripts, {0, 0}, &at);
  REQUIRE(both);
  const MathBox& s = child_of(*both, Role::superscript);
  const MathBox& b = child_of(*both, Role::subscript);
  CHECK(s.at.y() + s.ink.y1 < b.at.y() + b.ink.y0);  // the superscript's ink above the subscript's
  CHECK(s.at.x() == Approx(b.at.x()).margin(0.3 * em));  // one column beside the base
}

TEST_CASE("left and right delimiters are at least as tall as their content", "[typeset]") {
  for (const char* source : {R"(\left| \frac{a}{b} \right|)", R"(\left( \frac{\frac{1}{2}}{x^2} \right))",
                             R"(\left[ \sqrt{x^2 + y^2} \right])", R"(\left( x \right))"}) {
    INFO(source);
    Point at;
    const MathBox tree5 = set(source);
    const MathBox* d = find(tree5, Role::delimited, {0, 0}, &at);
    REQUIRE(d);
    const MathBox& content = child_of(*d, Role::base);
    int delimiters = 0;
    for (const MathBox& c : d->children) {
      if (c.role != Role::delimiter) continue;
      ++delimiters;
      CHECK(c.at.y() + c.ink.y0 <= content.at.y() + content.ink.y0);
      CHECK(c.at.y() + c.ink.y1 >= content.at.y() + content.ink.y1);
    }
    CHECK(delimiters == 2);
  }
}

TEST_CASE("operators are spaced as TeX spaces them: binary and relations apart, a sign close", "[typeset]") {
  const double em = 30;
  auto width = [&](const std::string& s) { return set(s, em).width; };
  // a + b: a medium space (4/18 em) each side of the plus.
  const double plain = width("a") + width("+") + width("b");
  CHECK(width("a + b") == Approx(plain + 2 * 4.0 / 18 * em).margin(0.2 * em));
  CHECK(width("a+b") == Approx(width("a + b")).margin(1e-9));  // spaces typed do not matter
  // a = b: a thick space (5/18 em) each side of a relation.
  CHECK(width("a = b") - (width("a") + width("=") + width("b")) > 2 * 4.5 / 18 * em);
  // -b: a sign, no space.
  CHECK(width("-b") == Approx(width("-") + width("b")).margin(0.02 * em));
  // \sin\theta: a thin space after the function name; \sin(x): none.
  CHECK(width(R"(\sin\theta)") > width(R"(\sin)") + width(R"(\theta)") + 2.0 / 18 * em);
}

TEST_CASE("spacing commands add their TeX widths in em: thin 3/18, medium 4/18, thick 5/18, negative -3/18, "
          "a control space 1/3, quad 1 and qquad 2",
          "[typeset]") {
  const double em = 36;
  const double ab = set("ab", em).width;
  const std::pair<const char*, double> spaces[] = {{R"(\,)", 3.0 / 18}, {R"(\:)", 4.0 / 18}, {R"(\>)", 4.0 / 18},
                                                   {R"(\;)", 5.0 / 18}, {R"(\!)", -3.0 / 18}, {R"(\ )", 1.0 / 3},
                                                   {R"(\quad)", 1}, {R"(\qquad)", 2}};
  for (const auto& [command, width] : spaces) {
    INFO(command);
    CHECK(set(std::string("a") + command + " b", em).width - ab == Approx(width * em).margin(1e-6));
  }
}

TEST_CASE("multi-line formulas stack their lines, the first baseline at the origin", "[typeset]") {
  const MathBox box = set(R"(u^{n+1} = u^n + \Delta t\, v^n \\ v^{n+1} = v^n + \Delta t\, a^n)");
  REQUIRE(box.children.size() == 2);
  CHECK(box.children[0].at.y() == 0);
  CHECK(box.children[1].at.y() - box.children[1].ascent > box.children[0].descent);  // no overlap
  CHECK(box.descent >= box.children[1].at.y());
}

TEST_CASE("nothing is clipped: the ink drawn lies inside the box reported, which is not much larger", "[typeset]") {
  std::vector<std::string> sources = {
      R"(\theta'' + \alpha|\theta'|\theta' + \sin\theta = 0)", R"(\frac{\Delta t^2}{2}\omega^2)",
      R"(\left| \frac{a}{b} \right| \le \sqrt{x^2 + y^2})", R"(\dot{u} = \bar{v},\; \hat{x} \approx \tilde{y})",
      R"(y^{n+1} = y^n + \Delta t\sum_{i=1}^{6} b_i k_i \\ \text{Fehlberg 4(5)})", R"(f\,f_j^2 \pm \mathbf{x})"};
  for (const auto& model : all_models()) sources.push_back(model.equation);
  for (const auto& scheme : all_schemes()) sources.emplace_back(scheme.formula);
  for (const int height : {360, 1080}) {
    for (const auto& source : sources) {
      for (const bool halo : {false, true}) {
        INFO(source << " at height " << height << (halo ? " with a halo" : ""));
        Canvas canvas = Canvas::image(2000, height > 400 ? 360 : 200);
        canvas.clear(palette::paper);
        // Sizes scale with the frame: this canvas is short, so set the size directly.
        const MathBox box = layout_formula(canvas, parse_formula(source), {height / 720.0 * 22 / canvas.scale()});
        MathPaint paint;
        paint.halo = halo;
        paint.halo_color = Color{1, 0.5, 0.5, 1};  // visible, so the halo's pixels count as ink too
        const PixelRect reported = draw_math(canvas, box, {20, 20 + box.ascent}, paint, source);
        const InkBox ink = drawn_pixels(canvas);
        REQUIRE_FALSE(ink.empty());
        CHECK(ink.x0 >= reported.x - 1e-9);
        CHECK(ink.y0 >= reported.y - 1e-9);
        CHECK(ink.x1 <= reported.x + reported.w + 1e-9);
        CHECK(ink.y1 <= reported.y + reported.h + 1e-9);
        // At most three pixels of slack each side (the pixel added for anti-aliasing, and rounding).
        CHECK(ink.x0 - reported.x <= 3);
        CHECK(ink.y0 - reported.y <= 3);
        CHECK(reported.x + reported.w - ink.x1 <= 3);
        CHECK(reported.y + reported.h - ink.y1 <= 3);
        // The layout's own ink box agrees with the pixels (without a halo, which reaches beyond it).
        if (!halo) CHECK(std::abs(box.ink.y0 + 20 + box.ascent - ink.y0) <= 1.5);
      }
    }
  }
}

TEST_CASE("a formula drawn on a recording canvas leaves its ink boxes for the label placer", "[typeset]") {
  Canvas canvas = Canvas::image(640, 360);
  DrawingRecord record;
  canvas.record_into(&record);
  const PixelRect drawn = draw_formula(canvas, R"(\frac{a}{b} + c)", {100, 100}, {22}, {});
  canvas.record_into(nullptr);
  int boxes = 0;
  InkBox covered;
  for (const OutlineShape& shape : record.outline.shapes()) {
    CHECK(shape.kind == OutlineKind::formula);
    covered.add({shape.bounds.x, shape.bounds.y, shape.bounds.x + shape.bounds.w, shape.bounds.y + shape.bounds.h});
    ++boxes;
  }
  CHECK(boxes == 5);  // a, the bar, b, +, c
  CHECK(covered.x0 == Approx(drawn.x));
  CHECK(covered.y1 == Approx(drawn.y + drawn.h));
  // A label asked for at the formula's centre is placed off it.
  LabelRequest label{"label", {}, drawn.center(), {1, 0}, 0};
  const auto placed = place_labels(canvas, {label}, record.outline, {0, 0, 640, 360});
  REQUIRE(placed.size() == 1);
  CHECK(placed[0].free);
  const PixelRect& box = placed[0].box;
  const bool apart = box.x >= drawn.x + drawn.w || box.x + box.w <= drawn.x || box.y >= drawn.y + drawn.h ||
                     box.y + box.h <= drawn.y;
  CHECK(apart);
}

TEST_CASE("sizes scale with the frame", "[typeset]") {
  const double small = set(R"(\theta'' + \sin\theta = 0)", 22, 360).width;
  const double large = set(R"(\theta'' + \sin\theta = 0)", 22, 1080).width;
  CHECK(large / small == Approx(1.5 / 0.7).epsilon(0.06));
}

TEST_CASE("rich text: words and math runs, broken between words", "[typeset]") {
  const auto runs = parse_rich_text(R"(drag takes $\alpha|\theta'|\theta'$ out, costs \$5)");
  REQUIRE(runs.size() == 3);
  CHECK_FALSE(runs[0].math);
  CHECK(runs[0].text == "drag takes ");
  CHECK(runs[1].math);
  CHECK(runs[2].text == " out, costs $5");
  Canvas canvas = Canvas::image(16, 720);
  const MathBox one = layout_rich_text(canvas, runs, {20});
  CHECK(one.children.size() == 1);
  const MathBox wrapped = layout_rich_text(canvas, runs, {20}, 0.5 * one.width);
  CHECK(wrapped.children.size() >= 2);
  for (const MathBox& line : wrapped.children) CHECK(line.width <= 0.5 * one.width + 1e-9);
  // Neighbouring words are set as one phrase.
  CHECK(leaf_texts(one).front() == "drag takes");
}

TEST_CASE("bad LaTeX gets one line naming the problem and the fix", "[typeset]") {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"(\foo + x)", "unknown command \\foo"},
      {R"(\thetaa)", "did you mean \\theta?"},
      {R"(\frac{a})", "needs an argument: write \\frac{a}{b}"},
      {R"(\frac)", "needs an argument"},
      {"{a + b", "a { is never closed: add the matching }"},
      {"a + b}", "a } closes nothing"},
      {"x^", "^ needs an argument: write x^2"},
      {"x_", "_ needs an argument"},
      {"x^a^b", "double superscript"},
      {"x_a_b", "double subscript"},
      {R"(\left( x)", "no matching \\right"},
      {R"(x \right))", "has no \\left"},
      {R"(\left< x \right>)", "\\left needs a delimiter"},
      {R"(\sqrt[3]{x})", "n-th root"},
      {R"(\text x)", "needs its text in braces"},
      {R"(\text{a \alpha})", "holds plain text"},
      {"a & b", "alignment"},
      {"50% off", "comment"},
      {"$x$", "formulas are math already"},
      {R"(\frac{a \\ b}{c})", "only at the top level"},
      {"x\\", "lone \\"},
      {"\xff", "not UTF-8"},
      {std::string(30, '{') + "x" + std::string(30, '}'), "nests deeper than"},
      {std::string(2000, 'x'), "too long"},
  };
  for (const auto& c : cases) {
    const std::string& source = c.first;
    const std::string& expected = c.second;
    INFO(source);
    const std::string message = error_of([&] { parse_formula(source); });
    CHECK(message.find(expected) != std::string::npos);
    CHECK(message.find('\n') == std::string::npos);
    CHECK(message.size() < 300);
  }
  CHECK(error_of([] { parse_rich_text("a $x + 1"); }).find("never closed") != std::string::npos);
  CHECK(error_of([] { parse_rich_text("a $\\foo$"); }).find("unknown command") != std::string::npos);
  CHECK(error_of([] { parse_rich_text("two\nlines"); }).find("one line") != std::string::npos);
}

TEST_CASE("deep but allowed nesting and long input take bounded work", "[typeset]") {
  std::string nested = "x";
  for (int i = 0; i < kMaxFormulaDepth - 1; ++i) nested = "{" + nested + "}^2";
  CHECK_NOTHROW(set(nested));
  std::string fractions;
  while (fractions.size() + 16 < kMaxFormulaLength) fractions += R"(\frac{1}{x} + )";
  fractions += "1";
  CHECK(set(fractions).width > 0);
}

TEST_CASE("every model's equation and every scheme's update formula typesets", "[typeset]") {
  for (const auto& model : all_models()) {
    INFO(model.name << ": " << model.equation);
    REQUIRE_FALSE(model.equation.empty());
    CHECK_NOTHROW(set(model.equation));
    CHECK_NOTHROW(set(model_equation(model, model_parameters(model))));
  }
  for (const auto& scheme : all_schemes()) {
    INFO(scheme.name << ": " << scheme.formula);
    REQUIRE_FALSE(scheme.formula.empty());
    CHECK_NOTHROW(set(std::string(scheme.formula)));
  }
}

TEST_CASE("a model's equation follows its settings when they change its form", "[typeset]") {
  auto equation = [](const std::string& model, const std::vector<std::string>& settings) {
    return model_equation(find_model(model), model_settings(model, settings));
  };
  CHECK(equation("pendulum", {}) == R"(\theta'' + \alpha|\theta'|\theta' + \sin\theta = 0)");
  CHECK(equation("pendulum", {"alpha=0"}) == R"(\theta'' + \sin\theta = 0)");
  CHECK(equation("vibration", {}) == R"(m u'' + k u = 0)");
  CHECK(equation("vibration", {"b=0.3"}) == R"(m u'' + b u' + k u = 0)");
  CHECK(equation("vibration", {"b=0.3", "damping=quadratic", "F=sin(t)"}) == R"(m u'' + b|u'|u' + k u = F(t))");
  CHECK(equation("vibration", {"s=u^3"}) == R"(m u'' + s(u) = 0)");
  CHECK(equation("resonance", {"beta=0"}) == R"(u'' + u = \sin(\gamma t))");
}

TEST_CASE("typeset, table-driven: the glyphs each formula sets and how its boxes stand to each other",
          "[typeset]") {
  // Relations of the script, fraction and function boxes, TeX's way (em = 30 px).
  enum class Relation { subscript_below_smaller, superscript_above_smaller, numerator_over_denominator, spaced, none };
  struct Case {
    const char* source;
    std::vector<std::string> glyphs;
    Relation relation;
  };
  const Case cases[] = {
      {R"(u_{n+1})", {"u", "n", "+", "1"}, Relation::subscript_below_smaller},
      {R"(x_i)", {"x", "i"}, Relation::subscript_below_smaller},
      {R"(\omega^2)", {"ω", "2"}, Relation::superscript_above_smaller},
      {R"(u^{n-1})", {"u", "n", "−", "1"}, Relation::superscript_above_smaller},
      {R"(\frac{g}{L})", {"g", "L"}, Relation::numerator_over_denominator},
      {R"(\frac{\Delta t}{2})", {"Δ", "t", "2"}, Relation::numerator_over_denominator},
      {R"(\mu\,\mathrm{sign})", {"μ", "s", "i", "g", "n"}, Relation::spaced},  // upright letters
      {R"(\sin\theta)", {"sin", "θ"}, Relation::spaced},
      {R"(\alpha\beta)", {"α", "β"}, Relation::none},
      {R"(\theta'')", {"θ", "″"}, Relation::none},
  };
  const double em = 30;
  for (const Case& c : cases) {
    INFO(c.source);
    const MathBox tree = set(c.source, em);
    CHECK(leaf_texts(tree) == c.glyphs);
    Point at;
    if (c.relation == Relation::subscript_below_smaller || c.relation == Relation::superscript_above_smaller) {
      const MathBox* scripts = find(tree, Role::scripts, {0, 0}, &at);
      REQUIRE(scripts);
      const bool sub = c.relation == Relation::subscript_below_smaller;
      const MathBox& script = child_of(*scripts, sub ? Role::subscript : Role::superscript);
      const MathBox& base = child_of(*scripts, Role::base);
      CHECK(glyph_leaves(script).front()->size < glyph_leaves(base).front()->size);   // smaller than its base
      CHECK((sub ? script.at.y() > base.at.y() : script.at.y() < base.at.y()));      // below or above its baseline
      CHECK(script.at.x() >= base.at.x() + base.width - 0.2 * em);                   // after the base
    } else if (c.relation == Relation::numerator_over_denominator) {
      const MathBox* fraction = find(tree, Role::fraction, {0, 0}, &at);
      REQUIRE(fraction);
      const MathBox& num = child_of(*fraction, Role::numerator);
      const MathBox& den = child_of(*fraction, Role::denominator);
      CHECK(num.at.y() + num.ink.y1 < den.at.y() + den.ink.y0);  // the numerator's ink wholly above
    } else if (c.relation == Relation::spaced) {
      // The second glyph run starts clear of the first: a visible gap (a thin space is 1/6 em, and
      // an operator's space after it, 1/6 em).
      std::vector<double> x0, x1;
      for_each_leaf(tree, {0, 0}, [&](const MathBox& leaf, const Point& origin) {
        if (leaf.role == Role::glyphs) x0.push_back(origin.x() + leaf.ink.x0), x1.push_back(origin.x() + leaf.ink.x1);
      });
      REQUIRE(x0.size() >= 2);
      CHECK(x0[1] - x1[0] >= em / 8);
    }
  }
}

TEST_CASE("a bracket and a parenthesis are drawn a tenth of the size inside their box: TeX-like side bearings",
          "[typeset]") {
  // At 30 px a bracket's box is 0.38 x 30 = 11.4 wide; its strokes keep 0.1 x 30 = 3 px from each side.
  const auto strokes = [](const std::string& source) {
    std::vector<const MathBox*> out;
    std::function<void(const MathBox&)> walk = [&](const MathBox& b) {
      if (b.role == Role::stroke) out.push_back(&b);
      for (const MathBox& c : b.children) walk(c);
    };
    const MathBox tree = set(source);
    walk(tree);
    std::vector<std::vector<double>> xs;
    for (const MathBox* s : out) {
      CHECK(s->width == Approx(11.4));
      xs.emplace_back();
      for (const Point& p : s->points) xs.back().push_back(p.x());
    }
    return xs;
  };
  const auto brackets = strokes("\\left[ x \\right]");
  REQUIRE(brackets.size() == 2);
  CHECK_THAT(brackets[0], Catch::Approx(std::vector<double>{8.4, 3, 3, 8.4}));
  CHECK_THAT(brackets[1], Catch::Approx(std::vector<double>{3, 8.4, 8.4, 3}));
  const auto parens = strokes("\\left( x \\right)");
  REQUIRE(parens.size() == 2);
  REQUIRE(parens[0].size() == 25);
  CHECK(parens[0].front() == Approx(8.4));  // the ends at the far side, the middle bulging to the near one
  CHECK(parens[0][12] == Approx(3));
  CHECK(parens[1][12] == Approx(8.4));
}

TEST_CASE("a bar is one upright stroke in the middle of its box, a double bar two at its thirds", "[typeset]") {
  // At 30 px a bar's box is 0.3 x 30 = 9 wide, a double bar's 0.45 x 30 = 13.5.
  const auto stroke_xs = [](const std::string& source) {
    std::vector<std::vector<double>> xs;
    std::function<void(const MathBox&)> walk = [&](const MathBox& b) {
      if (b.role == Role::stroke) {
        xs.emplace_back();
        for (const Point& p : b.points) xs.back().push_back(p.x());
      }
      for (const MathBox& c : b.children) walk(c);
    };
    walk(set(source));
    return xs;
  };
  const auto bars = stroke_xs("\\left| x \\right|");
  REQUIRE(bars.size() == 2);
  for (const auto& bar : bars) CHECK_THAT(bar, Catch::Approx(std::vector<double>{4.5, 4.5}));
  const auto double_bars = stroke_xs("\\left\\| x \\right\\|");
  REQUIRE(double_bars.size() == 4);
  for (size_t i = 0; i < 4; ++i) {
    const double third = i % 2 == 0 ? 0.33 * 13.5 : 0.67 * 13.5;
    CHECK_THAT(double_bars[i], Catch::Approx(std::vector<double>{third, third}));
  }
}
