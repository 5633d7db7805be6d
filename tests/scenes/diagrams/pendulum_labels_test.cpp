// What the pendulum's picture says, checked by meaning rather than by golden
// bytes: in an SVG still, each force's label reads its name and sits at its
// own arrow, and the arrows point where the forces do; each panel titled
// after a quantity plots that quantity's column.
//
// Cairo's SVG keeps no text: each glyph is a <symbol> (its outline) placed by
// <use x y>. A label is read by the shapes of its glyphs: the number of closed
// contours and whether it descends below the baseline tell S (one contour),
// D (two) and mg (one, then two with a descender) apart in any ordinary font.
// A label is tied to its arrow by colour: the arrows are drawn, then (placed
// once the whole diagram is known) the labels' glyphs, each force's in its
// arrow's colour; the panels, drawn before the diagram, do not count.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "svg_shapes.hpp"

#include <algorithm>
#include <cstdlib>

#include "core/models/model.hpp"
#include "scenes/diagrams/diagram_registry.hpp"
#include "scenes/config/scene_config.hpp"

using namespace vibra;
using namespace vibra::scenes;

namespace {
/// Pango markup without its tags: "<i>S</i> / <i>mg</i>" -> "S / mg".
std::string plain(const std::string& markup) {
  std::string text;
  bool in_tag = false;
  for (char c : markup) {
    if (c == '<') in_tag = true;
    else if (c == '>') in_tag = false;
    else if (!in_tag) text += c;
  }
  return text;
}

/// A glyph's outline: its closed contours and its box (y down, baseline 0).
struct Glyph {
  int contours = 0;
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

struct Point2 {
  double x = 0, y = 0;
};

/// A force arrow as drawn: its colour, where it starts, its tip, and the
/// glyphs of its label (the first group: the name; more groups follow, e.g. "×10").
struct DrawnArrow {
  std::string colour;
  Point2 from, tip;
  std::vector<std::vector<std::pair<std::string, Point2>>> label;  ///< glyph groups: symbol id and place
};

using vibra::test::svg::attribute;
using vibra::test::svg::numbers;

/// The colour in a style's "KEY:rgb(...)" ("" if none).
std::string colour(const std::string& style, const std::string& key) {
  const auto at = style.find(key + ":rgb(");
  if (at == std::string::npos) return "";
  return style.substr(at + key.size() + 1, style.find(')', at) + 1 - at - key.size() - 1);
}

struct Svg {
  std::map<std::string, Glyph> glyphs;
  std::vector<DrawnArrow> arrows;
  std::vector<std::pair<Point2, Point2>> lines;  ///< straight 2.2-wide strokes in the wire's colour (wire, ceiling)
};

Svg parse(const std::string& svg) {
  Svg out;
  std::string symbol;  // inside <symbol id=...>
  DrawnArrow* arrow = nullptr;     // the last arrow drawn, until its head
  DrawnArrow* labelled = nullptr;  // the arrow whose colour the current glyph group has
  for (size_t at = svg.find('<'); at != std::string::npos; at = svg.find('<', at + 1)) {
    const std::string tag = svg.substr(at, svg.find('>', at) + 1 - at);
    if (tag.rfind("<symbol", 0) == 0) {
      symbol = attribute(tag, "id");
    } else if (tag.rfind("</symbol", 0) == 0) {
      symbol.clear();
    } else if (tag.rfind("<path", 0) == 0) {
      const std::string style = attribute(tag, "style"), d = attribute(tag, "d");
      const auto xy = numbers(d);
      if (!symbol.empty()) {
        Glyph g;
        for (char c : d) g.contours += c == 'Z';
        for (size_t i = 0; i + 1 < xy.size(); i += 2) {
          g.x0 = std::min(g.x0, xy[i]), g.x1 = std::max(g.x1, xy[i]);
          g.y0 = std::min(g.y0, xy[i + 1]), g.y1 = std::max(g.y1, xy[i + 1]);
        }
        out.glyphs[symbol] = g;
        continue;
      }
      const bool straight = d.find('C') == std::string::npos && xy.size() == 4;
      if (style.find("stroke-width:4.2;") != std::string::npos && straight) {  // an arrow's shaft
        out.arrows.push_back({colour(style, "stroke"), {xy[0], xy[1]}, {xy[2], xy[3]}, {}});
        arrow = &out.arrows.back();
      } else if (arrow && style.find("stroke:none") != std::string::npos && colour(style, "fill") == arrow->colour) {
        arrow->tip = {xy[0], xy[1]};  // the head: its first point is the tip
        arrow = nullptr;
      } else if (style.find("stroke-width:2.2;") != std::string::npos && straight) {
        out.lines.push_back({{xy[0], xy[1]}, {xy[2], xy[3]}});
      }
    } else if (tag.rfind("<g style=", 0) == 0) {
      const std::string group = colour(attribute(tag, "style"), "fill");
      labelled = nullptr;
      for (auto& a : out.arrows)
        if (a.colour == group) labelled = &a;
      if (labelled) labelled->label.emplace_back();
    } else if (tag.rfind("</g", 0) == 0) {
      labelled = nullptr;
    } else if (tag.rfind("<use", 0) == 0 && labelled) {
      labelled->label.back().push_back({attribute(tag, "xlink:href").substr(1),
                                        {std::stod(attribute(tag, "x")), std::stod(attribute(tag, "y"))}});
    }
  }
  // Groups that held no glyphs (a colour's other fills) are not labels.
  for (auto& a : out.arrows) std::erase_if(a.label, [](const auto& group) { return group.empty(); });
  return out;
}

/// A label's name read from its first group of glyphs: S, D, mg, or "?".
std::string read_name(const Svg& svg, const DrawnArrow& a) {
  if (a.label.empty()) return "";
  std::string shapes;
  for (const auto& [id, place] : a.label[0]) {
    const Glyph& g = svg.glyphs.at(id);
    shapes += std::to_string(g.contours) + (g.y1 > 2 ? "d" : "") + " ";
  }
  if (shapes == "1 ") return "S";
  if (shapes == "2 ") return "D";
  if (shapes == "1 2d ") return "mg";
  return "? (" + shapes + ")";
}

/// The centre of a label's first group of glyphs.
Point2 label_centre(const Svg& svg, const DrawnArrow& a) {
  double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
  for (const auto& [id, p] : a.label.at(0)) {
    const Glyph& g = svg.glyphs.at(id);
    x0 = std::min(x0, p.x + g.x0), x1 = std::max(x1, p.x + g.x1);
    y0 = std::min(y0, p.y + g.y0), y1 = std::max(y1, p.y + g.y1);
  }
  return {(x0 + x1) / 2, (y0 + y1) / 2};
}

double distance(Point2 a, Point2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

int column_named(const std::vector<std::string>& columns, const std::string& name) {
  for (size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return int(i);
  FAIL("no column " << name);
  return -1;
}
}  // namespace

TEST_CASE("the pendulum's panel titled S plots the S column, D the D column, theta the angle in degrees",
          "[scene][diagram][labels]") {
  for (const char* scene : {"pendulum", "pendulum_book"}) {
    INFO("scene " << scene);
    const SceneConfig config = load_scene(scene);
    const Parameters p = model_parameters_of(config);
    auto run = find_model(config.model).build(p);
    const auto& columns = run->info().columns;
    const auto diagram = diagram_for(config).make({config, p, run->info()});
    // A row whose every column differs from the others, found by name.
    std::vector<double> row(columns.size());
    for (size_t i = 0; i < row.size(); ++i) row[i] = 0.1 * double(i + 1) + 0.0123;
    const struct {
      std::string title;  ///< the first word of a panel's title
      int column;
      double factor;
    } expected[] = {{"S", column_named(columns, "S"), 1},
                    {"D", column_named(columns, "D"), 1},
                    {"θ", column_named(columns, "theta"), 180 / M_PI}};
    int matched = 0;
    for (const PanelSpec& panel : diagram->panels()) {
      const std::string title = plain(panel.label);
      const std::string first = title.substr(0, title.find(' '));
      INFO("panel '" << title << "'");
      REQUIRE(!panel.series.empty());
      for (const auto& e : expected)
        if (first == e.title) {
          ++matched;
          CHECK(panel.series[0].value(row) == Approx(e.factor * row[e.column]).epsilon(1e-14));
        }
    }
    CHECK(matched == 3);  // every panel found, each once
  }
}

TEST_CASE("the pendulum's diagram's labels: S, mg and D each read so, at their own arrows, which point as the forces do",
          "[scene][diagram][labels]") {
  vibra::test::ScratchDirectory dir;
  for (const char* layout : {"fbd", "fbd+plot"}) {
    INFO("vibra render pendulum --at 1 --layout " << layout << " -o x.svg");
    const auto r = vibra::test::run_vibra(std::string("render pendulum --at 1 -q --layout ") + layout + " -o " + (dir / "x.svg"));
    REQUIRE(r.exit_code == 0);
    const Svg svg = parse(vibra::test::read_file(dir / "x.svg"));
    std::map<std::string, const DrawnArrow*> by_name;
    for (const auto& a : svg.arrows) {
      const std::string name = read_name(svg, a);
      INFO("an arrow from (" << a.from.x << ", " << a.from.y << ") to (" << a.tip.x << ", " << a.tip.y << ") labelled "
                              << name);
      CHECK(by_name.count(name) == 0);
      by_name[name] = &a;
    }
    REQUIRE(by_name.size() == 3);
    REQUIRE(by_name.count("S"));
    REQUIRE(by_name.count("mg"));
    REQUIRE(by_name.count("D"));
    const DrawnArrow &S = *by_name["S"], &mg = *by_name["mg"], &D = *by_name["D"];

    // Each label sits at its own arrow: mg and D beyond their tips, S beside
    // the middle of its shaft (its tip is on the wire, by the pivot), each
    // within 2 font heights and nearer its own arrow than the others.
    auto anchor = [](const DrawnArrow& a, bool beside) {
      return beside ? Point2{(a.from.x + a.tip.x) / 2, (a.from.y + a.tip.y) / 2} : a.tip;
    };
    const std::pair<const DrawnArrow*, bool> arrows[] = {{&S, true}, {&mg, false}, {&D, false}};
    for (const auto& [own, beside] : arrows) {
      const Point2 at = label_centre(svg, *own);
      INFO("label " << read_name(svg, *own) << " centred at (" << at.x << ", " << at.y << ")");
      CHECK(distance(at, anchor(*own, beside)) < 48);
      for (const auto& [other, other_beside] : arrows)
        if (other != own) {
          CHECK(distance(at, anchor(*own, beside)) < distance(at, anchor(*other, false)));
          CHECK(distance(at, anchor(*own, beside)) < distance(at, anchor(*other, true)));
        }
    }

    // The forces' directions: all from the bob's rim, one distance from its
    // centre (the wire's end) and pointing away from it; mg straight down; S
    // along the wire toward the pivot; D across the wire.
    CHECK(std::abs(mg.tip.x - mg.from.x) < 0.01);
    CHECK(mg.tip.y > mg.from.y + 20);
    const auto wire = std::find_if(svg.lines.begin(), svg.lines.end(), [&](const auto& l) {
      const double rim = distance(l.second, mg.from);
      return rim > 1 && std::abs(distance(l.second, S.from) - rim) < 0.01 &&
             std::abs(distance(l.second, D.from) - rim) < 0.01 && std::abs(l.second.x - mg.from.x) < 0.01;
    });
    REQUIRE(wire != svg.lines.end());  // from the pivot to the bob's centre
    for (const DrawnArrow* a : {&S, &mg, &D}) {
      const Point2 out{a->from.x - wire->second.x, a->from.y - wire->second.y}, f{a->tip.x - a->from.x, a->tip.y - a->from.y};
      CHECK((out.x * f.x + out.y * f.y) / std::hypot(out.x, out.y) / std::hypot(f.x, f.y) == Approx(1).margin(1e-4));
    }
    const Point2 up{wire->first.x - wire->second.x, wire->first.y - wire->second.y};
    auto cosine = [&](const DrawnArrow& a) {
      const Point2 f{a.tip.x - a.from.x, a.tip.y - a.from.y};
      return (f.x * up.x + f.y * up.y) / std::hypot(f.x, f.y) / std::hypot(up.x, up.y);
    };
    CHECK(cosine(S) == Approx(1).margin(1e-4));
    CHECK(cosine(D) == Approx(0).margin(1e-4));
  }
}

TEST_CASE("the wire's pull is drawn to its length S times the scale, its room inside the wire reaching near the pivot",
          "[scene][diagram][labels]") {
  // No drag, released from 60 degrees: energy gives omega^2 = 2 (cos theta -
  // cos 60), so S = omega^2 + cos theta = 3 cos theta - 1, largest (2) at the
  // bottom, where the scale makes it exactly its room, 0.85 of the wire
  // (PendulumDiagram::kInwardRoom): one unit of force is 0.85 / 2 wire
  // lengths. Each frame's S arrow, from the bob's rim (where every force
  // arrow starts) to its tip, is that long at the angle the drawn wire shows.
  vibra::test::ScratchDirectory dir;
  for (const char* at : {"0.3", "1.0", "1.6", "1.68"}) {
    INFO("vibra render pendulum --set alpha=0 --set Theta=60 --at " << at);
    const auto r = vibra::test::run_vibra(
        std::string("render pendulum --set alpha=0 --set Theta=60 --layout fbd -q --at ") + at + " -o " + (dir / "x.svg"));
    REQUIRE(r.exit_code == 0);
    const Svg svg = parse(vibra::test::read_file(dir / "x.svg"));
    const DrawnArrow* S = nullptr;
    for (const auto& a : svg.arrows)
      if (read_name(svg, a) == "S") S = &a;
    REQUIRE(S);
    // The wire: the 2.2-wide line that ends at the centre of the circle S starts on.
    const auto wire = std::find_if(svg.lines.begin(), svg.lines.end(), [&](const auto& l) {
      const Point2 along{l.first.x - l.second.x, l.first.y - l.second.y};
      const Point2 start{S->from.x - l.second.x, S->from.y - l.second.y};
      const double cross = along.x * start.y - along.y * start.x, reach = std::hypot(start.x, start.y);
      return reach > 1 && std::abs(cross) < 1e-3 * std::hypot(along.x, along.y) * reach;
    });
    REQUIRE(wire != svg.lines.end());
    const double length = distance(wire->first, wire->second);
    const double theta = std::atan2(wire->second.x - wire->first.x, wire->second.y - wire->first.y);  // y down
    const double S_exact = 3 * std::cos(theta) - 1;
    INFO("theta " << theta * 180 / M_PI << " deg, S " << S_exact);
    CHECK(distance(S->tip, S->from) / length == Approx(0.85 / 2 * S_exact).margin(0.004));
  }
}
