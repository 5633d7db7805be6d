// Lays out a parsed formula into boxes, with TeX's spacing, sizes and fractions.
#include "render/typeset/formula_layout.hpp"

#include <pango/pangocairo.h>

#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>

namespace vibra::render {

namespace {
using Role = MathBox::Role;

// TeX's spaces between atoms in mu (1/18 em), by the left and right atom's
// class (ord op bin rel open close punct inner); negative: only at the
// formula's own size, not in scripts (TeX's "(x)" entries).
constexpr std::array<std::array<int, 8>, 8> kSpacing = {{
    {0, 3, -4, -5, 0, 0, 0, -3},        // ord
    {3, 3, 0, -5, 0, 0, 0, -3},         // op
    {-4, -4, 0, 0, -4, 0, 0, -4},       // bin
    {-5, -5, 0, 0, -5, 0, 0, -5},       // rel
    {0, 0, 0, 0, 0, 0, 0, 0},           // open
    {0, 3, -4, -5, 0, 0, 0, -3},        // close
    {-3, -3, 0, -3, -3, -3, -3, -3},    // punct
    {-3, 3, -4, -5, -3, 0, -3, -3},     // inner
}};

double atom_space(Atom left, Atom right, bool script) {
  const int mu = kSpacing[static_cast<int>(left)][static_cast<int>(right)];
  if (mu < 0) return script ? 0 : -mu / 18.0;
  return mu / 18.0;
}

bool is_italic_glyphs(const MathBox& b) { return b.role == Role::glyphs && b.font == MathFont::italic; }

/// Appends `item` to a row or line with its origin at x on the baseline.
void append_at(MathBox& row, MathBox item, double x) {
  item.at = Point(x, 0);
  row.ascent = std::max(row.ascent, item.ascent);
  row.descent = std::max(row.descent, item.descent);
  row.ink.add(item.ink.moved(item.at));
  row.children.push_back(std::move(item));
}

class Typesetter {
 public:
  Typesetter(cairo_t* cr, double em, const char* family, bool bold_text = false)
      : cr_(cr), em_(em), family_(family), bold_text_(bold_text) {
    // The font's own proportions, measured once: the math axis (the middle
    // of the minus sign, where fraction bars sit) and the x-height.
    const MathBox minus = glyphs("−", MathFont::upright, em, Atom::bin);
    axis_ = minus.ink.empty() ? 0.25 : -0.5 * (minus.ink.y0 + minus.ink.y1) / em;
    const MathBox x = glyphs("x", MathFont::italic, em, Atom::ord);
    x_height_ = x.ink.empty() ? 0.5 : -x.ink.y0 / em;
  }

  /// A run of glyphs at `size` pixels per em: width from Pango's logical
  /// box, height and depth from its ink (so scripts and fractions sit on
  /// what is drawn), the ink box exact.
  MathBox glyphs(const std::string& text, MathFont font, double size, Atom atom) {
    const auto key = std::make_tuple(text, int(font), size);
    if (auto kept = measured_.find(key); kept != measured_.end()) {
      MathBox box = kept->second;
      box.atom = atom;
      return box;
    }
    PangoLayout* layout = pango_cairo_create_layout(cr_);
    PangoFontDescription* desc = pango_font_description_from_string(family_);
    pango_font_description_set_absolute_size(desc, size * PANGO_SCALE);
    if (font == MathFont::italic) pango_font_description_set_style(desc, PANGO_STYLE_ITALIC);
    if (font == MathFont::bold || (font == MathFont::text && bold_text_)) pango_font_description_set_weight(desc, PANGO_WEIGHT_BOLD);
    pango_layout_set_font_description(layout, desc);
    pango_font_description_free(desc);
    pango_layout_set_text(layout, text.c_str(), -1);
    PangoRectangle ink, logical;
    pango_layout_get_extents(layout, &ink, &logical);
    const double baseline = pango_layout_get_baseline(layout) / double(PANGO_SCALE);
    auto px = [](int v) { return v / double(PANGO_SCALE); };
    MathBox box;
    box.role = Role::glyphs;
    box.text = text;
    box.font = font;
    box.size = size;
    box.atom = atom;
    box.layout.reset(layout, g_object_unref);
    box.layout_offset = Point(-px(logical.x), -baseline);
    box.width = px(logical.width);
    if (ink.width > 0 && ink.height > 0) {
      box.ink = {px(ink.x) - px(logical.x), px(ink.y) - baseline, px(ink.x + ink.width) - px(logical.x),
                 px(ink.y + ink.height) - baseline};
      box.ascent = std::max(0.0, -box.ink.y0);
      box.descent = std::max(0.0, box.ink.y1);
      if (font == MathFont::italic) box.italic_correction = std::max(0.0, box.ink.x1 - box.width);
    }
    measured_.emplace(key, box);
    return box;
  }

  MathBox formula(const Formula& f) {
    std::vector<MathBox> lines;
    for (const MathNode& line : f.lines) {
      MathBox box = row(line.parts, em_, 0);
      box.role = Role::line;
      lines.push_back(std::move(box));
    }
    return stack(std::move(lines), em_);
  }

  /// Lines stacked, left-aligned, a comfortable distance apart; the origin on the first baseline.
  MathBox stack(std::vector<MathBox> lines, double size) {
    MathBox box;
    box.role = Role::row;
    double y = 0;
    for (size_t i = 0; i < lines.size(); ++i) {
      MathBox& line = lines[i];
      if (i > 0) y += std::max(lines[i - 1].descent + line.ascent + 0.3 * size, 1.25 * size);
      line.at = Point(0, y);
      box.width = std::max(box.width, line.width);
      box.ink.add(line.ink.moved(line.at));
      box.children.push_back(std::move(line));
    }
    box.ascent = box.children.empty() ? 0 : box.children.front().ascent;
    box.descent = box.children.empty() ? 0 : y + box.children.back().descent;
    return box;
  }

  double em() const { return em_; }
  double rule(double size) const { return std::max(1.0, 0.06 * size); }

  /// Items side by side with TeX's spaces between their classes.
  MathBox row(const std::vector<MathNode>& nodes, double size, int level) {
    std::vector<MathBox> items;
    items.reserve(nodes.size());
    for (const MathNode& n : nodes) items.push_back(node(n, size, level));
    // A binary operator with nothing to its left (a sign: -x, (-1)) or
    // nothing to its right is an ordinary symbol, as in TeX.
    int previous = -1;
    for (size_t i = 0; i < items.size(); ++i) {
      if (items[i].role == Role::space) continue;
      if (items[i].atom == Atom::bin) {
        const Atom before = previous < 0 ? Atom::open : items[previous].atom;
        if (previous < 0 || before == Atom::bin || before == Atom::op || before == Atom::rel || before == Atom::open ||
            before == Atom::punct)
          items[i].atom = Atom::ord;
      }
      if (previous >= 0 && items[previous].atom == Atom::bin &&
          (items[i].atom == Atom::rel || items[i].atom == Atom::close || items[i].atom == Atom::punct))
        items[previous].atom = Atom::ord;
      previous = int(i);
    }
    if (previous >= 0 && items[previous].atom == Atom::bin) items[previous].atom = Atom::ord;

    MathBox box;
    box.role = Role::row;
    box.children.reserve(items.size());  // `last` points into it
    double x = 0;
    const MathBox* last = nullptr;
    for (MathBox& item : items) {
      if (item.role != Role::space && last) {
        x += atom_space(last->atom, item.atom, level > 0) * size;
        // An italic letter leans into what follows unless that is italic too.
        if (is_italic_glyphs(*last) && !is_italic_glyphs(item)) x += last->italic_correction;
      }
      const double width = item.width;
      append_at(box, std::move(item), x);
      x += width;
      if (box.children.back().role != Role::space) last = &box.children.back();
    }
    box.width = std::max(0.0, x);
    if (box.children.size() == 1 && box.children.front().role != Role::space) {
      // A group of one keeps its class and lean (a braced operator, {x}^2).
      box.atom = box.children.front().atom;
      box.italic_correction = box.children.front().italic_correction;
    } else if (!box.children.empty()) {
      box.italic_correction = box.children.back().italic_correction;
    }
    return box;
  }

  MathBox node(const MathNode& n, double size, int level) {
    switch (n.kind) {
      case MathNode::Kind::glyphs: return symbol(n, size, level);
      case MathNode::Kind::group: {
        MathBox box = row(n.parts, size, level);
        if (n.atom != Atom::ord) box.atom = n.atom;
        return box;
      }
      case MathNode::Kind::space: {
        MathBox box;
        box.role = Role::space;
        box.width = n.space * size;
        return box;
      }
      case MathNode::Kind::fraction: return fraction(n, size, level);
      case MathNode::Kind::scripts: return scripts(n, size, level);
      case MathNode::Kind::radical: return radical(n, size, level);
      case MathNode::Kind::delimited: return delimited(n, size, level);
      case MathNode::Kind::accent: return accent(n, size, level);
    }
    return {};
  }

 private:
  double script_size(double size) const { return std::max(0.7 * size, 0.5 * em_); }

  MathBox symbol(const MathNode& n, double size, int level) {
    const bool large = n.atom == Atom::op && (n.glyphs == "∑" || n.glyphs == "∏" || n.glyphs == "∫");
    if (!large) return glyphs(n.glyphs, n.font, size, n.atom);
    // Large operators a size up at the formula's own level, centred on the axis.
    MathBox box = glyphs(n.glyphs, n.font, level == 0 ? 1.35 * size : size, n.atom);
    if (box.ink.empty()) return box;
    const double shift = -axis_ * size - 0.5 * (box.ink.y0 + box.ink.y1);
    MathBox row;
    row.role = Role::row;
    row.atom = n.atom;
    box.at = Point(0, shift);
    row.width = box.width;
    row.ink = box.ink.moved(box.at);
    row.ascent = std::max(0.0, -row.ink.y0);
    row.descent = std::max(0.0, row.ink.y1);
    row.children.push_back(std::move(box));
    return row;
  }

  MathBox rule_box(double width, double thickness) {
    MathBox bar;
    bar.role = Role::rule;
    bar.width = width;
    bar.ascent = thickness;
    bar.ink = {0, -thickness, width, 0};
    return bar;
  }

  MathBox stroke_box(std::vector<Point> points, double line_width, double width) {
    MathBox s;
    s.role = Role::stroke;
    s.width = width;
    s.line_width = line_width;
    for (const Point& p : points) s.ink.add({p.x(), p.y(), p.x(), p.y()});
    s.ink = s.ink.widened(0.5 * line_width);
    s.ascent = std::max(0.0, -s.ink.y0);
    s.descent = std::max(0.0, s.ink.y1);
    s.points = std::move(points);
    return s;
  }

  /// Places `child` at `at` inside `parent`, growing its ink; `role` names
  /// its part (a leaf keeps its own and is wrapped in a box of that role).
  static void put(MathBox& parent, MathBox child, const Point& at, std::optional<Role> role) {
    if (role && *role != child.role) {
      if (child.children.empty() && (child.role == Role::glyphs || child.role == Role::rule || child.role == Role::stroke)) {
        MathBox wrap;
        wrap.role = *role;
        wrap.width = child.width, wrap.ascent = child.ascent, wrap.descent = child.descent;
        wrap.ink = child.ink, wrap.atom = child.atom, wrap.italic_correction = child.italic_correction;
        child.at = Point(0, 0);
        wrap.children.push_back(std::move(child));
        child = std::move(wrap);
      } else {
        child.role = *role;
      }
    }
    child.at = at;
    parent.ink.add(child.ink.moved(at));
    parent.children.push_back(std::move(child));
  }

  MathBox fraction(const MathNode& n, double size, int level) {
    const double part_size = level == 0 ? std::max(0.85 * size, 0.5 * em_) : script_size(size);
    MathBox num = row(n.parts[0].kind == MathNode::Kind::group ? n.parts[0].parts : std::vector{n.parts[0]}, part_size, level + 1);
    MathBox den = row(n.parts[1].kind == MathNode::Kind::group ? n.parts[1].parts : std::vector{n.parts[1]}, part_size, level + 1);
    const double theta = rule(size), axis = axis_ * size, gap = std::max(1.5 * theta, 0.12 * size);
    const double overhang = 0.08 * size, pad = 0.1 * size;
    const double bar = std::max(num.width, den.width) + 2 * overhang;
    const double up = axis + 0.5 * theta + gap + num.descent;
    const double down = den.ascent + gap + 0.5 * theta - axis;
    MathBox box;
    box.role = Role::fraction;
    box.atom = Atom::inner;
    box.width = bar + 2 * pad;
    box.ascent = up + num.ascent;
    box.descent = down + den.descent;
    const double num_width = num.width, den_width = den.width;
    put(box, std::move(num), {pad + 0.5 * (bar - num_width), -up}, Role::numerator);
    put(box, rule_box(bar, theta), {pad, -(axis - 0.5 * theta)}, std::nullopt);
    put(box, std::move(den), {pad + 0.5 * (bar - den_width), down}, Role::denominator);
    return box;
  }

  MathBox scripts(const MathNode& n, double size, int level) {
    MathBox base = n.parts[0].kind == MathNode::Kind::group && n.parts[0].parts.empty() ? MathBox{} : node(n.parts[0], size, level);
    const bool simple = base.role == Role::glyphs;  // a character: scripts by the font alone
    const double s = script_size(size), theta = rule(size), xh = x_height_ * size;
    MathBox sup, sub;
    if (n.has_sup) sup = node(n.parts[1], s, level + 1);
    if (n.has_sub) sub = node(n.parts[2], s, level + 1);
    double u = simple ? 0 : base.ascent - 0.386 * s, v = simple ? 0 : base.descent + 0.05 * s;
    if (n.has_sup) u = std::max({u, 0.4 * size, sup.descent + 0.25 * xh});
    if (n.has_sub && !n.has_sup) v = std::max({v, 0.15 * size, sub.ascent - 0.8 * xh});
    if (n.has_sub && n.has_sup) {
      v = std::max(v, 0.247 * size);
      const double clearance = (u - sup.descent) - (sub.ascent - v);
      if (clearance < 4 * theta) v += 4 * theta - clearance;
      const double psi = 0.8 * xh - (u - sup.descent);
      if (psi > 0) u += psi, v -= psi;
    }
    MathBox box;
    box.role = Role::scripts;
    box.atom = base.atom;
    const double base_width = base.width, lean = base.italic_correction;
    box.ascent = base.ascent, box.descent = base.descent;
    double right = base_width;
    put(box, std::move(base), {0, 0}, Role::base);
    if (n.has_sup) {
      box.ascent = std::max(box.ascent, u + sup.ascent);
      right = std::max(right, base_width + lean + sup.width);
      put(box, std::move(sup), {base_width + lean, -u}, Role::superscript);
    }
    if (n.has_sub) {
      box.descent = std::max(box.descent, v + sub.descent);
      right = std::max(right, base_width + sub.width);
      put(box, std::move(sub), {base_width, v}, Role::subscript);
    }
    box.width = right + 0.05 * size;
    return box;
  }

  MathBox radical(const MathNode& n, double size, int level) {
    MathBox content = node(n.parts[0], size, level);
    const double theta = rule(size), clearance = theta + 0.25 * x_height_ * size;
    const double top = -(std::max(content.ascent, x_height_ * size) + clearance + 0.5 * theta);
    const double bottom = std::max(content.descent, 0.0) + 0.05 * size;
    const double h = std::min(bottom - top, size), sign = 0.55 * size;
    const double end = sign + content.width + 0.05 * size;
    MathBox box;
    box.role = Role::radical;
    box.atom = Atom::ord;
    box.width = end + 0.05 * size;
    std::vector<Point> path = {{0.03 * size, bottom - 0.45 * h}, {0.14 * size, bottom - 0.52 * h}, {0.3 * size, bottom},
                               {sign - 0.03 * size, top}, {end, top}};
    MathBox mark = stroke_box(std::move(path), theta, sign);
    box.ascent = std::max(content.ascent, mark.ascent);
    box.descent = std::max(content.descent, mark.descent);
    put(box, std::move(mark), {0, 0}, Role::delimiter);
    put(box, std::move(content), {sign, 0}, Role::base);
    return box;
  }

  /// A delimiter as a stroke reaching `half` above and below the axis.
  MathBox delimiter(const std::string& d, double half, double size) {
    const double axis = -axis_ * size, top = axis - half, bottom = axis + half;
    const double lw = std::max(1.0, 0.075 * size);
    if (d == ".") {
      MathBox none;
      none.role = Role::space;
      none.width = 0.12 * size;
      return none;
    }
    const double w = d == "‖" ? 0.45 * size : d == "|" ? 0.3 * size : 0.38 * size;
    const double near = 0.1 * size, far = w - 0.1 * size;
    std::vector<Point> path;
    if (d == "|") {
      path = {{0.5 * w, top}, {0.5 * w, bottom}};
    } else if (d == "‖") {
      MathBox both;
      both.role = Role::delimiter;
      both.width = w;
      MathBox left = stroke_box({{0.33 * w, top}, {0.33 * w, bottom}}, lw, w);
      MathBox right = stroke_box({{0.67 * w, top}, {0.67 * w, bottom}}, lw, w);
      both.ascent = left.ascent, both.descent = left.descent;
      put(both, std::move(left), {0, 0}, std::nullopt);
      put(both, std::move(right), {0, 0}, std::nullopt);
      return both;
    } else if (d == "(" || d == ")") {
      const int steps = 24;
      for (int i = 0; i <= steps; ++i) {
        const double t = double(i) / steps;
        const double bulge = std::sin(M_PI * t);
        path.emplace_back(d == "(" ? far - (far - near) * bulge : near + (far - near) * bulge, top + t * (bottom - top));
      }
    } else if (d == "[") {
      path = {{far, top}, {near, top}, {near, bottom}, {far, bottom}};
    } else if (d == "]") {
      path = {{near, top}, {far, top}, {far, bottom}, {near, bottom}};
    } else if (d == "⟨") {
      path = {{far, top}, {near, axis}, {far, bottom}};
    } else {  // ⟩
      path = {{near, top}, {far, axis}, {near, bottom}};
    }
    MathBox mark = stroke_box(std::move(path), lw, w);
    mark.role = Role::stroke;
    return mark;
  }

  MathBox delimited(const MathNode& n, double size, int level) {
    MathBox content = node(n.parts[0], size, level);
    const double axis = axis_ * size;
    // At least as tall as the content each side of the axis, and never
    // shorter than a parenthesis of the font.
    const double half = std::max({content.ascent - axis, content.descent + axis, 0.5 * size}) + 0.08 * size;
    MathBox open = delimiter(n.glyphs, half, size), close = delimiter(n.close, half, size);
    MathBox box;
    box.role = Role::delimited;
    box.atom = Atom::inner;
    const double open_width = open.width, content_width = content.width, close_width = close.width;
    box.ascent = std::max({content.ascent, open.ascent, close.ascent});
    box.descent = std::max({content.descent, open.descent, close.descent});
    put(box, std::move(open), {0, 0}, Role::delimiter);
    put(box, std::move(content), {open_width, 0}, Role::base);
    put(box, std::move(close), {open_width + content_width, 0}, Role::delimiter);
    box.width = open_width + content_width + close_width;
    return box;
  }

  MathBox accent(const MathNode& n, double size, int level) {
    MathBox base = node(n.parts[0], size, level);
    const InkBox under = base.ink.empty() ? InkBox{0, -x_height_ * size, base.width, 0} : base.ink;
    const double gap = 0.08 * size;
    // Over an italic letter the accent moves right with its slant.
    const double slant = is_italic_glyphs(base) ? 0.12 * -under.y0 : 0;
    const double centre = 0.5 * (under.x0 + under.x1) + slant;
    MathBox mark;
    if (n.glyphs.empty()) {  // \bar: a rule over the ink
      const double theta = rule(size);
      mark = rule_box(under.x1 - under.x0, theta);
      mark.at = Point(centre - 0.5 * mark.width, under.y0 - gap);
    } else {
      mark = glyphs(n.glyphs, MathFont::upright, size, Atom::ord);
      const double x = centre - 0.5 * (mark.ink.x0 + mark.ink.x1), y = under.y0 - gap - mark.ink.y1;
      mark.at = Point(x, y);
    }
    MathBox box;
    box.role = Role::accent;
    box.atom = base.atom;
    box.width = base.width;
    box.italic_correction = base.italic_correction;
    const Point mark_at = mark.at;
    box.descent = base.descent;
    put(box, std::move(base), {0, 0}, Role::base);
    put(box, std::move(mark), mark_at, std::nullopt);
    box.ascent = std::max(0.0, -box.ink.y0);
    return box;
  }

  cairo_t* cr_;
  double em_;
  const char* family_;
  bool bold_text_;
  double axis_ = 0.25, x_height_ = 0.5;  ///< in em
  std::map<std::tuple<std::string, int, double>, MathBox> measured_;
};
}  // namespace

MathBox layout_formula(Canvas& canvas, const Formula& formula, const MathStyle& style) {
  Typesetter setter(canvas.cr(), style.size * canvas.scale(), style.family, style.bold_text);
  return setter.formula(formula);
}

namespace {
/// A piece lines break between: a word, or a formula whole.
struct Piece {
  std::string word;  ///< a word; empty for a formula
  MathBox box;       ///< a formula's box, or the word measured alone
  bool space_before = false;
};

std::vector<Piece> rich_text_pieces(Typesetter& setter, const std::vector<RichRun>& runs, double em) {
  std::vector<Piece> pieces;
  bool pending_space = false;
  for (const RichRun& run : runs) {
    if (run.math) {
      pieces.push_back({"", setter.formula(run.formula), pending_space});
      pending_space = false;
      continue;
    }
    size_t i = 0;
    while (i < run.text.size()) {
      if (run.text[i] == ' ') {
        pending_space = true, ++i;
        continue;
      }
      const size_t end = std::min(run.text.find(' ', i), run.text.size());
      std::string word = run.text.substr(i, end - i);
      MathBox box = setter.glyphs(word, MathFont::text, em, Atom::ord);
      pieces.push_back({std::move(word), std::move(box), pending_space && !pieces.empty()});
      pending_space = false;
      i = end;
    }
    // A space at the end of a text run separates it from the formula after it.
  }
  return pieces;
}

/// Greedy lines of at most `max_width` (0: one line).
std::vector<std::vector<const Piece*>> greedy_lines(const std::vector<Piece>& pieces, double space, double max_width) {
  std::vector<std::vector<const Piece*>> lines(1);
  double x = 0;
  for (const Piece& p : pieces) {
    const double advance = (lines.back().empty() ? 0 : p.space_before ? space : 0) + p.box.width;
    if (max_width > 0 && !lines.back().empty() && x + advance > max_width) lines.emplace_back(), x = 0;
    x += lines.back().empty() ? p.box.width : advance;
    lines.back().push_back(&p);
  }
  return lines;
}

/// One line's box: its neighbouring words set as one run (kerning, and one
/// Pango layout for a phrase), its formulas as they are.
MathBox line_box(Typesetter& setter, const std::vector<const Piece*>& line, double space, double em) {
  MathBox box;
  box.role = Role::line;
  // Every text line is at least the font's height, so lines keep an even pitch.
  box.ascent = 0.8 * em, box.descent = 0.25 * em;
  double at = 0;
  for (size_t i = 0; i < line.size();) {
    if (i > 0 && line[i]->space_before) at += space;
    MathBox item;
    if (line[i]->word.empty()) {
      item = line[i]->box;
      ++i;
    } else {
      std::string phrase = line[i]->word;
      for (++i; i < line.size() && !line[i]->word.empty(); ++i) phrase += (line[i]->space_before ? " " : "") + line[i]->word;
      item = setter.glyphs(phrase, MathFont::text, em, Atom::ord);
    }
    const double width = item.width;
    append_at(box, std::move(item), at);
    at += width;
  }
  box.width = at;
  return box;
}
}  // namespace

MathBox layout_rich_text(Canvas& canvas, const std::vector<RichRun>& runs, const MathStyle& style, double max_width) {
  const double em = style.size * canvas.scale();
  Typesetter setter(canvas.cr(), em, style.family, style.bold_text);
  const std::vector<Piece> pieces = rich_text_pieces(setter, runs, em);
  const double space = setter.glyphs("a a", MathFont::text, em, Atom::ord).width -
                       2 * setter.glyphs("a", MathFont::text, em, Atom::ord).width;
  std::vector<MathBox> boxes;
  for (const auto& line : greedy_lines(pieces, space, max_width)) boxes.push_back(line_box(setter, line, space, em));
  return setter.stack(std::move(boxes), em);
}

}  // namespace vibra::render
