// Tick labels of linear axes: plain decimals for everyday ranges; tiny,
// huge or offset ranges share a power of ten and an offset stated once.
#include <catch2/catch.hpp>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "render/plot/axis.hpp"
#include "render/labels/drawing_record.hpp"
#include "render/plot/plot_panel.hpp"

using vibra::render::linear_tick_labels;
using vibra::render::LinearTickLabels;
using vibra::render::nice_ticks;

namespace {
double number(const std::string& s) {
  const std::string minus = "\u2212";
  return s.compare(0, minus.size(), minus) == 0 ? -std::stod(s.substr(minus.size())) : std::stod(s);
}

/// Characters, not bytes: the minus sign takes three bytes.
size_t characters(const std::string& s) {
  size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return n;
}

/// The value a tick label stands for, with the axis's common factor and offset.
double value_of(const std::string& label, const LinearTickLabels& labels) {
  double scale = 1, offset = 0;
  std::string common = labels.common;
  const std::string sup = "×10<sup>";
  if (common.rfind(sup, 0) == 0) {
    const size_t end = common.find("</sup>");
    scale = std::pow(10.0, number(common.substr(sup.size(), end - sup.size())));
    common = common.substr(end + 6);
  }
  if (!common.empty()) {
    const size_t sign = common.find_first_not_of(' ');
    const bool minus = common.compare(sign, std::string("\u2212").size(), "\u2212") == 0;
    offset = (minus ? -1 : 1) * number(common.substr(common.find(' ', sign) + 1));
  }
  return offset + number(label) * scale;
}

LinearTickLabels labels_for(double lo, double hi) {
  const auto ticks = nice_ticks(lo, hi, 5);
  REQUIRE(ticks.size() >= 2);
  return linear_tick_labels(ticks, ticks[1] - ticks[0]);
}
}  // namespace

TEST_CASE("axis labels: everyday ranges get plain decimals and no common factor", "[render][axis]") {
  const LinearTickLabels l = labels_for(-1.2, 1.2);
  CHECK(l.common.empty());
  CHECK(l.labels.front() == "\u22121.0");
  CHECK(l.labels.back() == "1.0");
}

TEST_CASE("axis labels: a drift of 1e-9 reads in units of 10^-9 stated once", "[render][axis]") {
  const LinearTickLabels l = labels_for(-1.2e-9, 2.4e-9);
  CHECK(l.common == "×10<sup>\u22129</sup>");
  CHECK(l.labels.front() == "\u22121");
  CHECK(l.labels.back() == "2");
}

TEST_CASE("axis labels: ticks differing far below their size get an offset", "[render][axis]") {
  const LinearTickLabels l = labels_for(1 - 2e-9, 1 + 3e-9);
  CHECK(l.common == "×10<sup>\u22129</sup> + 1");
  CHECK(l.labels.front() == "\u22122");
}

TEST_CASE("axis labels: every tiny, huge or offset range labels distinct ticks that read back their values",
          "[render][axis]") {
  for (double centre : {0.0, 1.0, -1000.0, 3e6, 1e12})
    for (double span : {1e-13, 1e-9, 1e-6, 1e-3, 1.0, 1e3, 1e7}) {
      if (centre != 0 && span < 1e-13 * std::abs(centre) * 1e3) continue;  // beyond double precision
      const auto ticks = nice_ticks(centre - 0.3 * span, centre + 0.7 * span, 5);
      const double step = ticks[1] - ticks[0];
      const LinearTickLabels l = linear_tick_labels(ticks, step);
      INFO("centre " << centre << ", span " << span << ", common '" << l.common << "'");
      REQUIRE(l.labels.size() == ticks.size());
      CHECK(std::set<std::string>(l.labels.begin(), l.labels.end()).size() == ticks.size());
      for (size_t i = 0; i < ticks.size(); ++i) {
        CHECK(characters(l.labels[i]) <= 8);  // short: what differs, not the digits all share
        CHECK(std::abs(value_of(l.labels[i], l) - ticks[i]) <= 1e-3 * step);
      }
    }
}

TEST_CASE("a panel's axes get as many ticks as their labels leave room for: up to six across and five up", "[axis]") {
  // 0..12 across a wide panel: six steps of 2 fit (five would need steps of
  // 5); up, -1..1 over a tall panel: five steps of 0.5. A narrow panel gets fewer.
  using namespace vibra::render;
  const auto labels_drawn = [](double width, double height) {
    PlotPanel panel({0, 0, width, height}, 1);
    panel.set_x_range(0, 12);
    panel.set_y_range(-1 / 1.1, 1 / 1.1);  // -1..1 with set_y_range's margin
    Canvas canvas = Canvas::image(int(width), int(height));
    DrawingRecord record;
    canvas.record_into(&record);
    panel.draw_axes(canvas, "<i>u</i>", "<i>t</i>");
    canvas.record_into(nullptr);
    std::vector<std::string> texts;
    for (const auto& shape : record.outline.shapes())
      if (shape.kind == OutlineKind::text) texts.push_back(shape.name);
    return std::set<std::string>(texts.begin(), texts.end());
  };
  const std::set<std::string> wide = labels_drawn(1280, 600);
  for (const char* x : {"0", "2", "4", "6", "8", "10", "12"}) CHECK(wide.count(x) == 1);
  for (const char* y : {"\u22121.0", "\u22120.5", "0.0", "0.5", "1.0"}) CHECK(wide.count(y) == 1);
  const std::set<std::string> narrow = labels_drawn(180, 600);
  CHECK(narrow.count("2") == 0);  // too little room for a tick every 2
}

TEST_CASE("a panel's tick labels sit beside their ticks: y labels end 6 px left of the frame, x labels 4 px under it",
          "[axis]") {
  using namespace vibra::render;
  for (const double scale : {0.5, 1.0, 1.5}) {
    INFO("scale " << scale);
    const PixelRect outer{0, 0, 1280 * scale, 600 * scale};
    PlotPanel panel(outer, scale);
    panel.set_x_range(0, 12);
    panel.set_y_range(-1 / 1.1, 1 / 1.1);  // -1..1 with set_y_range's margin
    Canvas canvas = Canvas::image(int(outer.w), int(outer.h));
    DrawingRecord record;
    canvas.record_into(&record);
    panel.draw_axes(canvas, "<i>u</i>", "<i>t</i>");
    canvas.record_into(nullptr);
    const PixelRect& area = panel.area();
    int y_labels = 0, x_labels = 0;
    for (const auto& shape : record.outline.shapes()) {
      if (shape.kind != OutlineKind::text) continue;
      INFO("'" << shape.name << "' at " << shape.bounds.x << "," << shape.bounds.y << " " << shape.bounds.w << "x"
               << shape.bounds.h);
      const Point centre = shape.bounds.center();
      if (shape.name.find('.') != std::string::npos) {  // -1.0 ... 1.0 up the left
        ++y_labels;
        CHECK(shape.bounds.x + shape.bounds.w == Approx(area.x - 6 * scale).margin(2));
        CHECK(centre.y() == Approx(panel.to_pixel(0, value_of(shape.name, {})).y()).margin(2));
      } else if (shape.name.find_first_not_of("0123456789") == std::string::npos) {  // 0 ... 12 along the bottom
        ++x_labels;
        CHECK(shape.bounds.y == Approx(area.y + area.h + 4 * scale).margin(2));
        CHECK(centre.x() == Approx(panel.to_pixel(number(shape.name), 0).x()).margin(2));
      }
    }
    CHECK(y_labels == 5);
    CHECK(x_labels == 7);
  }
}
