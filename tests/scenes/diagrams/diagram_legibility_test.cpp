// What makes a frame legible on a projector, checked from the kit's recorded
// outlines: tick labels that keep apart on small panels, legends clear of
// the data, a force-scale key per diagram, and a pendulum support that its
// own swing does not cut.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "render/draw/canvas.hpp"
#include "render/labels/drawing_record.hpp"
#include "render/labels/outline.hpp"
#include "render/plot/plot_panel.hpp"
#include "cli_support.hpp"
#include "png_compare.hpp"
#include "scenes/diagrams/forces/force_key.hpp"
#include "scenes/config/scene_config.hpp"
#include "scene_run_support.hpp"
#include "scenes/scene_factory.hpp"

using vibra::render::Canvas;
using vibra::render::DrawingRecord;
using vibra::render::OutlineKind;
using vibra::render::OutlineShape;
using vibra::render::PixelRect;

namespace {

bool boxes_overlap(const PixelRect& a, const PixelRect& b) {
  return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

/// The text boxes a panel's axes write, as recorded.
std::vector<PixelRect> axis_text_boxes(int width, int height, const PixelRect& outer, double y0, double y1) {
  Canvas canvas = Canvas::image(width, height);
  DrawingRecord record;
  canvas.record_into(&record);
  vibra::render::PlotPanel panel(outer, canvas.scale());
  panel.set_x_range(0, 18.85);
  panel.set_y_range(y0, y1);
  panel.draw_axes(canvas, "<i>u</i>  displacement", "<i>t</i>");
  canvas.record_into(nullptr);
  std::vector<PixelRect> boxes;
  for (const OutlineShape& shape : record.outline.shapes())
    if (shape.kind == OutlineKind::text) boxes.push_back(shape.bounds);
  return boxes;
}

/// Draws a scene's run and returns the outline of the frame at `moment`
/// (0 = first step, 1 = last), the static layer included.
DrawingRecord frame_at(const std::string& scene_name, const std::vector<vibra::scenes::Setting>& settings,
                       double moment) {
  vibra::scenes::SceneConfig config = vibra::scenes::load_scene(scene_name);
  for (const auto& s : settings) vibra::scenes::apply_setting(config, s);
  long long steps = 0;
  auto scene = vibra::test::scene_after_pre_pass(config, steps);
  const std::vector<double> row = vibra::test::observed_row_at(*scene, config, steps, moment);
  Canvas canvas = Canvas::image(config.width, config.height);
  scene->draw(canvas, row);
  REQUIRE(scene->last_layout());
  return *scene->last_layout();
}

PixelRect bounds_of(const DrawingRecord& frame, OutlineKind kind) {
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (const OutlineShape& s : frame.outline.shapes())
    if (s.kind == kind) {
      x0 = std::min(x0, s.bounds.x), y0 = std::min(y0, s.bounds.y);
      x1 = std::max(x1, s.bounds.x + s.bounds.w), y1 = std::max(y1, s.bounds.y + s.bounds.h);
    }
  return {x0, y0, x1 - x0, y1 - y0};
}

}  // namespace

TEST_CASE("tick labels never touch, down to a 320x180 frame", "[legibility][panels]") {
  struct Case {
    int width, height;
    PixelRect outer;
    double y0, y1;
  };
  // A panel of the default layout at each size, and a tall one; ranges of
  // a unit amplitude and of an awkward span.
  const std::vector<Case> cases = {{320, 180, {150, 7, 165, 80}, -1, 1},      {320, 180, {150, 7, 165, 80}, -0.37, 2.9},
                                   {640, 360, {300, 10, 330, 170}, -1, 1},    {1280, 720, {590, 10, 680, 350}, -1, 1},
                                   {1920, 1080, {880, 15, 1030, 520}, -3e-4, 7e-4}};
  for (const Case& c : cases) {
    const std::vector<PixelRect> boxes = axis_text_boxes(c.width, c.height, c.outer, c.y0, c.y1);
    INFO(c.width << "x" << c.height << ", y from " << c.y0 << " to " << c.y1);
    // The y label, the t label and at least two ticks on each axis.
    CHECK(boxes.size() >= 6);
    for (size_t i = 0; i < boxes.size(); ++i)
      for (size_t j = i + 1; j < boxes.size(); ++j) {
        INFO("text boxes " << i << " and " << j);
        CHECK_FALSE(boxes_overlap(boxes[i], boxes[j]));
      }
  }
}

TEST_CASE("the force key's arrow stands for a round force and is long enough to read", "[legibility][forces]") {
  for (double world_per_force : {0.6, 1e-4, 3.3, 0.0123, 250.0})
    for (double zoom : {37.0, 180.0, 411.0})
      for (double scale : {0.7, 1.0, 1.5}) {
        const vibra::scenes::ForceKey key{world_per_force, "N", ""};
        const double f = vibra::scenes::force_key_value(key, zoom, scale);
        INFO("world per force " << world_per_force << ", zoom " << zoom << ", scale " << scale << ": force " << f);
        REQUIRE(f > 0);
        const double mantissa = f / std::pow(10, std::floor(std::log10(f) + 1e-12));
        CHECK((std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 || std::abs(mantissa - 5) < 1e-9));
        const double pixels = f * world_per_force * zoom / scale;  // in 720p pixels
        CHECK(pixels >= 30 - 1e-9);
        CHECK(pixels <= 75 + 1e-9);
      }
  CHECK(vibra::scenes::force_key_value({0, "N", ""}, 100, 1) == 0);
  CHECK(vibra::scenes::force_key_value({NAN, "N", ""}, 100, 1) == 0);
}

TEST_CASE("a diagram with force arrows shows its force key, saying what is drawn at another scale",
          "[legibility][forces]") {
  auto key_texts = [](const std::string& scene, const std::vector<vibra::scenes::Setting>& settings) {
    std::vector<std::string> texts;
    const DrawingRecord frame = frame_at(scene, settings, 0.1);
    for (const OutlineShape& s : frame.outline.shapes())
      if (s.kind == OutlineKind::text && s.name.rfind("= ", 0) == 0) texts.push_back(s.name);
    return texts;
  };
  const auto pendulum = key_texts("pendulum", {});
  REQUIRE(pendulum.size() == 1);
  CHECK(pendulum[0].find("<i>mg</i>") != std::string::npos);
  CHECK(pendulum[0].find("<i>D</i> drawn \u00d75") != std::string::npos);
  // Without drag there is no D arrow, and the key does not mention one.
  const auto undamped = key_texts("pendulum", {{"alpha", "0", "test"}});
  REQUIRE(undamped.size() == 1);
  CHECK(undamped[0].find("<i>D</i>") == std::string::npos);
  const auto box = key_texts("sliding_box", {});
  REQUIRE(box.size() == 1);
  CHECK(box[0].find("not to scale") != std::string::npos);
  CHECK(key_texts("rlc", {}).empty());  // a circuit has no force arrows
}

TEST_CASE("the pendulum's drag arrow says how much longer it is drawn than to scale: D, D ×2, D ×2.5",
          "[legibility][forces]") {
  struct Expected {
    const char* magnification;
    std::string label, note;  ///< the arrow's label, and what the force key says of it ("" for nothing)
  };
  const Expected cases[] = {{"1", "<i>D</i>", ""},
                            {"2", "<i>D</i> \u00d72", "<i>D</i> drawn \u00d72"},
                            {"2.5", "<i>D</i> \u00d72.5", "<i>D</i> drawn \u00d72.5"}};
  for (const Expected& e : cases) {
    INFO("drag_magnification = " << e.magnification);
    // Theta = 90 degrees, moving: the drag is large enough to draw an arrow.
    const DrawingRecord frame =
        frame_at("pendulum", {{"drag_magnification", e.magnification, "test"}, {"Omega", "60", "test"}}, 0.1);
    std::vector<std::string> drag_labels, keys;
    for (const auto& request : frame.labels)
      if (request.markup.rfind("<i>D</i>", 0) == 0) drag_labels.push_back(request.markup);
    for (const OutlineShape& s : frame.outline.shapes())
      if (s.kind == OutlineKind::text && s.name.rfind("= ", 0) == 0) keys.push_back(s.name);
    CHECK(drag_labels == std::vector<std::string>{e.label});
    REQUIRE(keys.size() == 1);
    if (e.note.empty()) CHECK(keys[0].find("drawn") == std::string::npos);
    else CHECK(keys[0].find(e.note) != std::string::npos);
  }
}

TEST_CASE("the force key names each force drawn, in its arrow's colour, clear of the drawing", "[legibility][forces]") {
  auto names_in = [](const std::string& scene, const std::vector<vibra::scenes::Setting>& settings) {
    std::vector<std::string> names;
    const DrawingRecord frame = frame_at(scene, settings, 0.3);
    for (const OutlineShape& s : frame.outline.shapes()) {
      if (s.kind != OutlineKind::text) continue;
      for (const char* force : {"gravity", "wire force", "air drag", "spring", "damping", "damper", "friction",
                                "driving force", "forcing", "weight, floor", "wire (spring) force", "weight",
                                "at rest", "static load"})
        if (s.name.size() > std::strlen(force) && s.name.compare(s.name.size() - std::strlen(force), std::string::npos, force) == 0) {
          names.push_back(s.name);
          // A name covers nothing the diagram draws.
          for (const OutlineShape& other : frame.outline.shapes())
            if (other.kind == OutlineKind::body || other.kind == OutlineKind::spring || other.kind == OutlineKind::arrow ||
                other.kind == OutlineKind::wire || other.kind == OutlineKind::ground) {
              INFO(scene << ": '" << s.name << "' and a " << vibra::render::outline_kind_name(other.kind));
              CHECK_FALSE(vibra::render::overlaps(s.bounds, other));
            }
        }
    }
    return names;
  };
  using Names = std::vector<std::string>;
  CHECK(names_in("pendulum", {}) == Names{"<i>mg</i> gravity", "<i>S</i> wire force", "<i>D</i> air drag"});
  CHECK(names_in("pendulum", {{"alpha", "0", "test"}}) == Names{"<i>mg</i> gravity", "<i>S</i> wire force"});
  CHECK(names_in("spring", {}) == Names{"−<i>ku</i> spring"});
  CHECK(names_in("spring_dashpot", {}) ==
        Names{"−<i>ku</i> spring", "−<i>bu</i>′ damping", "<i>F</i>(<i>t</i>) driving force"});
  CHECK(names_in("sliding_box", {}).size() == 3);
  CHECK(names_in("washing_machine", {}).size() == 3);
  CHECK(names_in("bumpy_road", {}) == Names{"−<i>ku</i> spring beyond its static load", "−<i>bu</i>′ damper"});
  CHECK(names_in("bouncing_ball", {}) == Names{"<i>mg</i> weight", "<i>N</i> ground, at rest"});
  // The elastic pendulum's scene has no drag (gamma = 0): no D named.
  CHECK(names_in("elastic_pendulum", {}) == Names{"<i>mg</i> gravity", "<i>S</i> wire (spring) force"});
  CHECK(names_in("elastic_pendulum", {{"gamma", "0.05", "test"}}).size() == 3);
}

TEST_CASE("a panel's legend sits on its title row, off the data, where the row has room", "[legibility][panels]") {
  auto legend_boxes = [](int width, int height, const PixelRect& outer, bool margin_below_free = false,
                         const std::string& third = "") {
    Canvas canvas = Canvas::image(width, height);
    vibra::render::PlotPanel panel(outer, canvas.scale());
    DrawingRecord record;
    canvas.record_into(&record);
    std::vector<vibra::render::PlotPanel::LegendItem> items{{"numerical", vibra::render::palette::ink},
                                                             {"exact", vibra::render::palette::ink, true}};
    if (!third.empty()) items.push_back({third, vibra::render::palette::faint, true});
    panel.draw_legend(canvas, items, "<i>u</i>  displacement", margin_below_free);
    canvas.record_into(nullptr);
    std::vector<PixelRect> boxes;
    for (const OutlineShape& s : record.outline.shapes())
      if (s.kind == OutlineKind::text) boxes.push_back(s.bounds);
    return std::pair(boxes, panel.area());
  };
  for (auto [width, height, outer] : {std::tuple{640, 360, PixelRect{300, 10, 330, 170}},
                                      std::tuple{1920, 1080, PixelRect{880, 15, 1030, 520}}}) {
    const auto [boxes, area] = legend_boxes(width, height, outer);
    INFO(width << "x" << height);
    REQUIRE(boxes.size() == 2);
    for (const PixelRect& b : boxes) {
      CHECK(b.y + b.h <= area.y + 0.5);  // above the plot's frame
      CHECK(b.x + b.w <= area.x + area.w + 0.5);
    }
  }
  // Too narrow a row (the washing machine's u panel at 640x360): under the
  // plot when no tick labels are there (a panel stacked above another)...
  const PixelRect stacked{295, 5, 340, 170};
  const auto [under, plot] = legend_boxes(640, 360, stacked, true, "±steady amplitude");
  REQUIRE(under.size() == 3);
  for (const PixelRect& b : under) {
    CHECK(b.y >= plot.y + plot.h);  // below the plot's frame
    CHECK(b.y + b.h <= stacked.y + stacked.h + 1);  // inside the panel
    CHECK(b.x + b.w <= plot.x + plot.w + 0.5);
  }
  // ... else inside the plot's top-right corner.
  const auto [inside, area] = legend_boxes(640, 360, stacked, false, "±steady amplitude");
  REQUIRE(inside.size() == 3);
  for (const PixelRect& b : inside) CHECK(b.y >= area.y);
  const auto [small, small_area] = legend_boxes(320, 180, {150, 7, 100, 80}, true);
  REQUIRE(small.size() == 2);
  for (const PixelRect& b : small) CHECK(b.y >= small_area.y);  // wider than the plot: inside it
}

TEST_CASE("a pendulum that swings up past its pivot hangs from a bearing block, not a ceiling", "[legibility][pendulum]") {
  // The bob's diameter (L/10) measures the support: a ceiling is 0.6 L wide
  // (six diameters), the block 0.14 L and its outline's stroke.
  auto support_in_diameters = [](const std::vector<vibra::scenes::Setting>& settings) {
    const DrawingRecord frame = frame_at("pendulum", settings, 0.05);
    const PixelRect bob = bounds_of(frame, OutlineKind::body), support = bounds_of(frame, OutlineKind::ground);
    REQUIRE(bob.w > 0);
    REQUIRE(support.w > 0);
    return support.w / bob.w;
  };
  CHECK(support_in_diameters({{"Theta", "60", "test"}}) > 4);
  CHECK(support_in_diameters({{"Theta", "170", "test"}, {"alpha", "0", "test"}}) < 2);
  CHECK(support_in_diameters({{"Theta", "100", "test"}}) < 2);
}

TEST_CASE("the pendulum's geometry (Fig 1.21): i_r, i_theta, (x0, y0) and L are drawn and labelled, clear of the rest",
          "[legibility][pendulum]") {
  const std::vector<std::string> wanted = {"<b>i</b><sub><i>r</i></sub>", "<b>i</b><sub><i>θ</i></sub>",
                                           "(<i>x</i><sub>0</sub>, <i>y</i><sub>0</sub>)", "<i>L</i>"};
  auto arrows = [](const DrawingRecord& frame) {
    return std::count_if(frame.outline.shapes().begin(), frame.outline.shapes().end(),
                         [](const OutlineShape& s) { return s.kind == OutlineKind::arrow; });
  };
  for (double moment : {0.03, 0.1, 0.25}) {
    INFO("at " << moment << " of the run");
    const DrawingRecord plain = frame_at("pendulum", {}, moment);
    const DrawingRecord frame = frame_at("pendulum", {{"annotate", "geometry", "test"}}, moment);
    for (const std::string& markup : wanted) {
      INFO("label " << markup);
      const auto placed = std::find_if(frame.placed.begin(), frame.placed.end(),
                                       [&](const vibra::render::PlacedLabel& p) { return p.request.markup == markup; });
      REQUIRE(placed != frame.placed.end());
      CHECK(placed->free);  // on no body, wire, arrow or other label
    }
    for (const auto& p : plain.placed) CHECK(std::find(wanted.begin(), wanted.end(), p.request.markup) == wanted.end());
    CHECK(arrows(frame) > arrows(plain));  // the two unit vectors
  }
}

TEST_CASE("a frame under 360 pixels high is the 360-pixel picture made smaller, not a squeeze", "[legibility][cli]") {
  CHECK(vibra::render::scale_for_height(360) == 0.7);
  CHECK(vibra::render::scale_for_height(180) == 0.35);
  CHECK(vibra::render::scale_for_height(1080) == 1.5);
  // The thumbnail against the 640x360 still scaled down: the same picture
  // (25 dB; a layout squeezed into 320x180 at 640x360's text size gave 15).
  vibra::test::ScratchDirectory dir;
  for (const char* scene : {"pendulum", "spring_dashpot --panels u,phase,energy --energy-bars"}) {
    INFO(scene);
    const std::string common = std::string("render ") + scene + " --at 2 -q -o ";
    REQUIRE(vibra::test::run_vibra(common + (dir / "large.png") + " --size 640x360").exit_code == 0);
    REQUIRE(vibra::test::run_vibra(common + (dir / "small.png") + " --size 320x180").exit_code == 0);
    vibra::test::shell("ffmpeg -v error -y -i '" + (dir / "large.png") + "' -vf scale=320:180:flags=area '" +
                       (dir / "halved.png") + "'");
    CHECK(vibra::test::psnr(dir / "small.png", dir / "halved.png") > 21);
  }
}

TEST_CASE("no line is drawn thinner than a pixel, so a thumbnail's lines stay dark", "[legibility][render]") {
  // At 320x180 a 2-pixel line of 720p is 0.7 of a pixel: antialiased, it
  // would cover 70% of its row and come out grey. It is widened to a pixel.
  Canvas canvas = Canvas::image(320, 180);
  REQUIRE(canvas.scale() == 0.35);
  canvas.clear(vibra::render::palette::paper);
  DrawingRecord record;
  canvas.record_into(&record);
  cairo_t* cr = canvas.cr();
  cairo_move_to(cr, 20, 90.5);  // along the middle of row 90
  cairo_line_to(cr, 300, 90.5);
  cairo_set_line_width(cr, 2 * canvas.scale());
  cairo_set_source_rgb(cr, 0, 0, 0);
  canvas.stroke();
  canvas.record_into(nullptr);
  canvas.flush();
  const auto green = [&](int x, int y) { return (reinterpret_cast<const std::uint32_t*>(canvas.data() + y * canvas.stride())[x] >> 8) & 255; };
  CHECK(green(160, 90) == 0);  // the whole row covered: black, not grey
  CHECK(green(160, 89) > 200);  // and no wider than the pixel
  CHECK(green(160, 91) > 200);
  REQUIRE(record.outline.shapes().size() == 1);
  CHECK(record.outline.shapes()[0].half_width == Approx(0.5));  // the label placer sees what is drawn
}

TEST_CASE("the force key keeps to its width: a note too long for the scale's line takes a row of its own",
          "[legibility][forces]") {
  // At 640x360 beside energy bars, under a caption of two lines, "force
  // scale -> = 2 mg   (burst: impulse at impact)" ran under the bars' labels.
  const std::string caption = "h0 = 1 m · <i>C</i><sub>R</sub> = 0.8 · ε<sub>v</sub> = 0.1 m/s · Δ<i>t</i> = 0.00903 s · "
                              "velocity-verlet";
  // Each scene and whether its key has a note (what is drawn at another scale).
  const std::pair<const char*, int> scenes_notes[] = {{"bouncing_ball", 1}, {"sliding_box", 1},     {"pendulum", 1},
                                                      {"washing_machine", 1}, {"bumpy_road", 1}, {"elastic_pendulum", 0},
                                                      {"spring_dashpot", 1},  {"spring", 1}};
  for (const auto& [name, has_note] : scenes_notes)
    for (const auto& [width, height] : {std::pair{640, 360}, std::pair{1280, 720}}) {
      INFO(name << " at " << width << "x" << height);
      vibra::scenes::SceneConfig config = vibra::scenes::load_scene(name);
      vibra::scenes::apply_setting(config, {"energy_bars", "true", "test"});
      config.width = width, config.height = height;
      auto run = vibra::scenes::build_scene_runs(config);
      auto scene = vibra::scenes::make_scene_for(config, *run, caption);
      std::vector<double> row(run->width());
      run->row(row);
      scene->record(row);
      while (run->advance()) run->row(row), scene->record(row);
      Canvas canvas = Canvas::image(width, height);
      scene->draw(canvas, row);
      const vibra::render::Outline& outline = scene->last_layout()->outline;
      auto is_bar_label = [](const OutlineShape& s) {
        return s.kind == OutlineKind::text &&
               (s.name == "kinetic" || s.name == "potential" || s.name == "dissipated" || s.name == "work of F");
      };
      REQUIRE(std::count_if(outline.shapes().begin(), outline.shapes().end(), is_bar_label) >= 3);
      int notes = 0, scales = 0;
      for (const OutlineShape& s : outline.shapes()) {
        if (s.kind != OutlineKind::text) continue;
        const bool scale_line = s.name.rfind("= ", 0) == 0, own_row = s.name.rfind("(", 0) == 0;
        if (!scale_line && !own_row && s.name != "force scale") continue;
        scales += scale_line;
        notes += own_row || s.name.find("   (") != std::string::npos;
        for (const OutlineShape& label : outline.shapes())
          if (is_bar_label(label)) {
            INFO("'" << s.name << "' and the bars' label '" << label.name << "'");
            CHECK_FALSE(boxes_overlap(s.bounds, label.bounds));
          }
      }
      CHECK(scales == 1);
      CHECK(notes == has_note);
    }
}
