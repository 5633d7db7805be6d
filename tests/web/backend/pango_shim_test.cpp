// The browser build's Pango: markup parsed into runs, layouts measured and drawn as text runs where Pango would put them.
#include <pango/pangocairo.h>

#include <catch2/catch.hpp>
#include <memory>

#include "shim_recording.hpp"
#include "web/canvas/surface_commands.hpp"
#include "web/canvas/text_measure.hpp"
#include "web/shim/pango_markup.hpp"

using vibra::web::test::Recording;
using vibra::web::test::recording;

namespace {

std::shared_ptr<PangoLayout> layout_of(cairo_t* cr, const char* markup, double size) {
  std::shared_ptr<PangoLayout> layout(pango_cairo_create_layout(cr), g_object_unref);
  PangoFontDescription* font = pango_font_description_from_string("DejaVu Sans");
  pango_font_description_set_absolute_size(font, size * PANGO_SCALE);
  pango_layout_set_font_description(layout.get(), font);
  pango_font_description_free(font);
  pango_layout_set_markup(layout.get(), markup, -1);
  return layout;
}

}  // namespace

TEST_CASE("markup becomes runs with italic, sizes, rises and entities", "[web-backend]") {
  const auto runs = vibra::web::shim::parse_markup("<i>m</i>g &amp; <i>ε</i><sub>v</sub>&#960;");
  REQUIRE(runs.size() == 5);
  CHECK((runs[0].text == "m" && runs[0].style.italic));
  CHECK((runs[1].text == "g & " && !runs[1].style.italic));
  CHECK(runs[2].text == "ε");
  // <sub>: DejaVu's OS/2 subscript size and drop, as Pango 1.50 sets it (7.871 px under 11.25 px text).
  CHECK((runs[3].text == "v" && runs[3].style.scale == Approx(1433.0 / 2048) &&
         runs[3].style.rise == Approx(-286.0 / 2048)));
  CHECK(runs[4].text == "π");
  CHECK_THROWS_AS(vibra::web::shim::parse_markup("<blink>x</blink>"), std::invalid_argument);
}

TEST_CASE("a layout is measured by the text measure and drawn at its baseline from the current point",
          "[web-backend]") {
  const Recording r = recording(200, 100);
  const auto& s = r.surface;
  const auto& cr = r.cr;
  const auto layout = layout_of(cr.get(), "<i>m</i>g", 20);
  PangoRectangle ink, logical;
  pango_layout_get_pixel_extents(layout.get(), &ink, &logical);
  // Native builds measure 0.6 em a character: two characters of 20 px.
  CHECK((logical.x == 0 && logical.y == 0 && logical.width == 24));
  // Pango's hinted line at 20 px: ascent 19 and descent 5 whole pixels (not 18.56 and 4.72).
  CHECK(logical.height == 24);
  CHECK(pango_layout_get_baseline(layout.get()) == 19 * PANGO_SCALE);
  cairo_move_to(cr.get(), 10, 30);
  cairo_set_source_rgb(cr.get(), 0, 0, 0);
  pango_cairo_show_layout(cr.get(), layout.get());
  const auto& commands = vibra::web::commands_of(s.get());
  CHECK(commands.joined_strings() == "italic 20.000px 'DejaVu Sans'\nm\n20.000px 'DejaVu Sans'\ng");
  const double baseline = 30 + 19;
  const std::vector<double>& n = commands.numbers();
  // The second run starts one advance (12 px) further along the same baseline.
  REQUIRE(n.size() == 3 + 2 * 19);  // the move, then two text operations of 19 numbers
  CHECK((n[3] == double(vibra::web::Op::kText) && n[3 + 15] == 10 && n[3 + 16] == Approx(baseline)));
  CHECK((n[22 + 15] == 22 && n[22 + 16] == Approx(baseline)));
}

TEST_CASE("a layout shown at a fractional point sets its glyphs at whole pixels, as Cairo's image compositor",
          "[web-backend]") {
  const Recording r = recording(200, 100);
  const auto& s = r.surface;
  const auto& cr = r.cr;
  const auto layout = layout_of(cr.get(), "x", 20);
  cairo_move_to(cr.get(), 10.3, 30.6);
  pango_cairo_show_layout(cr.get(), layout.get());
  const std::vector<double>& n = vibra::web::commands_of(s.get()).numbers();
  REQUIRE(n.size() == 3 + 19);
  CHECK((n[3 + 15] == 10 && n[3 + 16] == 50));  // (10.3, 30.6 + 19) rounded, not (10.3, 49.6)
}

TEST_CASE("a superscript raises the line's baseline and a subscript lowers its bottom, as native Pango",
          "[web-backend]") {
  const Recording r = recording(200, 100);
  const auto& cr = r.cr;
  // Native Pango 1.50's baselines of "10<sup>−8</sup>x": 13.3994 px at 11.25 px, 17.2002 px at 15 px (the
  // superscript 983/2048 em up, its own hinted ascent over that), where plain text has 11 and 14.
  CHECK(pango_layout_get_baseline(layout_of(cr.get(), "10<sup>−8</sup>x", 11.25).get()) == 13721);
  CHECK(pango_layout_get_baseline(layout_of(cr.get(), "10<sup>−8</sup>x", 15).get()) == 17613);
  CHECK(pango_layout_get_baseline(layout_of(cr.get(), "10x", 15).get()) == 14 * PANGO_SCALE);
  // A subscript 286/2048 em down lowers the line's bottom: native height 19.0947 px of "C<sub>R</sub>x" at 15 px.
  PangoRectangle logical;
  pango_layout_get_extents(layout_of(cr.get(), "C<sub>R</sub>x", 15).get(), nullptr, &logical);
  CHECK(logical.height == 19553);
}

TEST_CASE("a line's ascent and descent are the whole pixels native Pango gives DejaVu Sans", "[web-backend]") {
  // pango_layout_get_baseline and the logical height of native Pango 1.50 on
  // an image surface, at these sizes in pixels (65.717 px: 61.0002 px of
  // ascent in doubles, 61 in FreeType's fixed point).
  struct Line {
    double size;
    int baseline, height;
  };
  const Line lines[] = {{10, 10, 13}, {12, 12, 15}, {14, 13, 17}, {14.4, 14, 18},
                        {16.8, 16, 20}, {20, 19, 24}, {28, 26, 33}, {65.717, 61, 77}};
  for (const Line& line : lines) {
    INFO(line.size << " px");
    CHECK(vibra::web::hinted_ascent(line.size) == line.baseline);
    CHECK(vibra::web::hinted_ascent(line.size) + vibra::web::hinted_descent(line.size) == line.height);
  }
}

TEST_CASE("text laid on the path is stroked with the pen, as a label's halo", "[web-backend]") {
  const Recording r = recording(200, 100);
  const auto& s = r.surface;
  const auto& cr = r.cr;
  const auto layout = layout_of(cr.get(), "x", 10);
  cairo_move_to(cr.get(), 0, 0);
  pango_cairo_layout_path(cr.get(), layout.get());
  cairo_set_line_width(cr.get(), 4);
  cairo_stroke(cr.get());
  const std::string text = vibra::web::describe(vibra::web::commands_of(s.get()));
  CHECK(text.rfind("moveTo 0 0\nstroke ", 0) == 0);
  CHECK(text.find("\ntext 1 0 0 0 1 4 0 0 1 0 0 1 0 0 0 ") != std::string::npos);
}

TEST_CASE("a layout wider than its width ends in an ellipsis that fits", "[web-backend]") {
  const Recording r = recording(200, 100);
  const auto& cr = r.cr;
  const auto layout = layout_of(cr.get(), "abcdefghij", 10);  // 60 px
  pango_layout_set_width(layout.get(), 30 * PANGO_SCALE);
  pango_layout_set_ellipsize(layout.get(), PANGO_ELLIPSIZE_END);
  PangoRectangle logical;
  pango_layout_get_pixel_extents(layout.get(), nullptr, &logical);
  CHECK(logical.width == 30);  // "abcd…": five characters of 6 px
}

TEST_CASE("each glyph advances a whole number of pixels, as Pango's hinted metrics on an image", "[web-backend]") {
  const Recording r = recording(200, 100);
  const auto& s = r.surface;
  const auto& cr = r.cr;
  const auto layout = layout_of(cr.get(), "abc", 11);  // 6.6 px a glyph, measured
  PangoRectangle logical;
  pango_layout_get_pixel_extents(layout.get(), nullptr, &logical);
  CHECK(logical.width == 21);  // each advance within the run, 6.6 px, rounded: 7 + 7 + 7, not 19.8
  cairo_move_to(cr.get(), 0, 0);
  pango_cairo_show_layout(cr.get(), layout.get());
  const std::vector<double>& n = vibra::web::commands_of(s.get()).numbers();
  REQUIRE(n.size() == 3 + 3 * 19);  // the move, then a text operation a glyph
  CHECK((n[3 + 15] == 0 && n[22 + 15] == 7 && n[41 + 15] == 14));
}

namespace {
/// DejaVu Sans at 11.25 px as the browser measures it: 'r' 4.625 px and 'e'
/// 6.92 px alone, "re" 0.43 px tighter (its kerning), every other text 6 px a character.
vibra::web::TextExtent kerned_measure(const std::string&, double, const std::string& text) {
  const double advance = text == "r" ? 4.625 : text == "e" ? 6.92 : text == "re" ? 11.115 : 6.0 * text.size();
  return {advance, 0, advance, 8, 0};
}
}  // namespace

TEST_CASE("a glyph's advance carries its kerning with the next glyph before it is rounded, as harfbuzz and Pango",
          "[web-backend]") {
  const Recording r = recording(200, 100);
  const auto& s = r.surface;
  const auto& cr = r.cr;
  const vibra::web::MeasureText before = vibra::web::text_measure();
  vibra::web::set_text_measure(kerned_measure);
  const auto layout = layout_of(cr.get(), "re", 11.25);
  cairo_move_to(cr.get(), 0, 0);
  pango_cairo_show_layout(cr.get(), layout.get());
  PangoRectangle logical;
  pango_layout_get_pixel_extents(layout.get(), nullptr, &logical);
  vibra::web::set_text_measure(before);
  // Native Pango sets "wire force" at 11.25 px with 'r' 4 px wide: 4.625 - 0.43 rounded, not 4.625 rounded.
  const std::vector<double>& n = vibra::web::commands_of(s.get()).numbers();
  REQUIRE(n.size() == 3 + 2 * 19);
  CHECK((n[3 + 15] == 0 && n[22 + 15] == 4));
  CHECK(logical.width == 11);  // 4 + round(6.92)
}
