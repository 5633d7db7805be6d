// What a lecturer adds to a render: a title and the equation of motion
// across the top, the schemes' update formulas in a comparison's legend,
// notes shown while their time lasts, and a caption with units.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <tuple>
#include <vector>

#include "cli_support.hpp"
#include "core/error.hpp"
#include "core/models/model.hpp"
#include "render/labels/drawing_record.hpp"
#include "scenes/overlays/note.hpp"
#include "render/draw/color.hpp"
#include "scenes/overlays/note_callouts.hpp"
#include "scenes/overlays/run_caption.hpp"
#include "scenes/config/scene_config.hpp"
#include "scenes/figures/plot_scene.hpp"
#include "scenes/scene_factory.hpp"
#include "scenes/system_scene.hpp"
#include "test_support.hpp"

using namespace vibra;

namespace {

struct Run {
  scenes::SceneConfig config;
  std::unique_ptr<Trajectory> runs;
  std::vector<std::vector<double>> rows;
  std::unique_ptr<scenes::Scene> scene;
};

/// A scene with its pre-pass done over every row.
Run prepared(const std::string& name, const std::vector<std::pair<std::string, std::string>>& settings) {
  Run r;
  r.config = scenes::load_scene(name);
  for (const auto& [k, v] : settings) scenes::apply_setting(r.config, {k, v, "test"});
  r.runs = scenes::build_scene_runs(r.config);
  r.scene = scenes::make_scene_for(r.config, *r.runs, "a caption");
  r.rows = test::rows(*scenes::build_scene_runs(r.config));
  for (const auto& row : r.rows) r.scene->record(row);
  return r;
}

bool same_pixels(const render::Canvas& a, const render::Canvas& b) {
  a.flush(), b.flush();
  for (int y = 0; y < a.height(); ++y)
    if (std::memcmp(a.data() + y * a.stride(), b.data() + y * b.stride(), 4 * size_t(a.width())) != 0) return false;
  return true;
}

/// The bounding box of the pixels that differ between two pictures of one size.
render::PixelRect differing(const render::Canvas& a, const render::Canvas& b) {
  a.flush(), b.flush();
  int x0 = a.width(), y0 = a.height(), x1 = -1, y1 = -1;
  for (int y = 0; y < a.height(); ++y) {
    const auto* pa = reinterpret_cast<const std::uint32_t*>(a.data() + y * a.stride());
    const auto* pb = reinterpret_cast<const std::uint32_t*>(b.data() + y * b.stride());
    for (int x = 0; x < a.width(); ++x)
      if (pa[x] != pb[x]) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  if (x1 < 0) return {};
  return {double(x0), double(y0), double(x1 - x0 + 1), double(y1 - y0 + 1)};
}

/// The row nearest time t.
size_t r_index(const std::vector<std::vector<double>>& rows, double t) {
  size_t best = 0;
  for (size_t i = 0; i < rows.size(); ++i)
    if (std::abs(rows[i][0] - t) < std::abs(rows[best][0] - t)) best = i;
  return best;
}

bool inside(const render::PixelRect& inner, const render::PixelRect& outer) {
  return inner.x >= outer.x - 1e-9 && inner.y >= outer.y - 1e-9 && inner.x + inner.w <= outer.x + outer.w + 1e-9 &&
         inner.y + inner.h <= outer.y + outer.h + 1e-9;
}

bool apart(const render::PixelRect& a, const render::PixelRect& b) {
  return a.x + a.w <= b.x || b.x + b.w <= a.x || a.y + a.h <= b.y || b.y + b.h <= a.y;
}

}  // namespace

TEST_CASE("the caption names the settings with their units, dt and the scheme", "[lecture]") {
  auto caption = [](const std::string& model, const std::vector<std::string>& settings) {
    const Parameters p = model_settings(model, settings);
    return scenes::run_caption(model, p, find_model(model).build(p)->info().mesh);
  };
  CHECK(caption("pendulum", {"Theta=60", "alpha=0.4", "scheme=rk4", "steps_per_period=120"}) ==
        "<i>Θ</i> = 60° · <i>α</i> = 0.4 · Δ<i>t</i> = 0.05236 · rk4");
  CHECK(caption("bumpy-road", {"m=60", "k=4*1e4", "dt=0.001"}) ==
        "<i>m</i> = 60 kg · <i>k</i> = 4e+04 N/m · Δ<i>t</i> = 0.001 s · centered");
  CHECK(caption("pendulum", {"Theta=0.5rad", "C_D=0.5", "rho=1.2", "L=1", "m=1", "R=0.1"}) ==
        "<i>Θ</i> = 0.5 rad · <i>L</i> = 1 m · <i>m</i> = 1 kg · <i>R</i> = 0.1 m · <i>C</i><sub>D</sub> = 0.5 · "
        "<i>ρ</i> = 1.2 kg/m³ · Δ<i>t</i> = 0.1047 · rk4");
  // Scaled models' dimension words are no units.
  CHECK(caption("vibration", {"m=2", "k=4", "dt=0.05"}) == "<i>m</i> = 2 · <i>k</i> = 4 · Δ<i>t</i> = 0.05 · centered");
  CHECK(caption("vibration", {"F=sin(t)"}) == "<i>F</i> = sin(t) · Δ<i>t</i> = 0.1571 · centered");
}

TEST_CASE("a title and the equation take a band across the top and the rest lays out below it", "[lecture]") {
  for (const auto& [w, h] : {std::pair{640, 360}, {1920, 1080}, {1280, 720}}) {
    for (const std::string layout : {"fbd+plot", "fbd"}) {
      INFO(w << "x" << h << " " << layout);
      Run r = prepared("pendulum", {{"size", std::to_string(w) + "x" + std::to_string(h)}, {"layout", layout},
                                    {"title", "The damped pendulum"}, {"equation", "true"}});
      auto* scene = dynamic_cast<scenes::SystemScene*>(r.scene.get());
      REQUIRE(scene);
      const scenes::FrameHeading& heading = scene->heading();
      REQUIRE(heading.title_box());
      REQUIRE(heading.equation_box());
      const render::PixelRect frame{0, 0, double(w), double(h)};
      CHECK(inside(*heading.title_box(), frame));
      CHECK(inside(*heading.equation_box(), frame));
      CHECK(apart(*heading.title_box(), *heading.equation_box()));
      CHECK(heading.equation_box()->y + heading.equation_box()->h <= heading.height());
      CHECK(scene->diagram_area().y >= heading.height());
      // Legible: the equation's em is at least 15 pixels even at 640x360.
      CHECK(heading.equation_box()->h >= 15);
      CHECK(heading.height() <= 0.2 * h);
      render::Canvas canvas = render::Canvas::image(w, h);
      scene->draw(canvas, r.rows[r.rows.size() / 3]);
      // Drawn, and recorded: the labels' outline holds the title's and the equation's ink.
      int formula_shapes = 0;
      for (const auto& shape : scene->last_layout()->outline.shapes())
        formula_shapes += shape.kind == render::OutlineKind::formula;
      CHECK(formula_shapes >= 8);
      for (const auto& label : scene->last_layout()->placed) CHECK(label.box.y >= heading.height());
    }
  }
  // Without them, no band.
  Run plain = prepared("pendulum", {});
  CHECK(dynamic_cast<scenes::SystemScene&>(*plain.scene).heading().height() == 0);
}

TEST_CASE("the plot layout draws its title and equation too, in the band above its panels", "[lecture]") {
  Run r = prepared("spring", {{"size", "640x360"}, {"layout", "plot"}, {"title", "The undamped spring"},
                              {"equation", "true"}});
  auto* scene = dynamic_cast<scenes::PlotScene*>(r.scene.get());
  REQUIRE(scene);
  const scenes::FrameHeading& heading = scene->heading();
  REQUIRE(heading.title_box());
  REQUIRE(heading.equation_box());
  render::Canvas canvas = render::Canvas::image(640, 360);
  scene->draw(canvas, r.rows[r.rows.size() / 3]);
  canvas.flush();
  // Ink: pixels much darker than the white background, inside each box.
  auto dark_pixels = [&](const render::PixelRect& box) {
    int dark = 0;
    for (int y = std::max(0, int(box.y)); y < std::min(360, int(box.y + box.h) + 1); ++y)
      for (int x = std::max(0, int(box.x)); x < std::min(640, int(box.x + box.w) + 1); ++x) {
        const std::uint8_t* p = canvas.data() + y * canvas.stride() + 4 * x;  // B, G, R, A
        dark += p[0] + p[1] + p[2] < 3 * 128;
      }
    return dark;
  };
  CHECK(dark_pixels(*heading.title_box()) > 50);
  CHECK(dark_pixels(*heading.equation_box()) > 30);
  CHECK(heading.equation_box()->y + heading.equation_box()->h <= heading.height());
}

TEST_CASE("an equation wider than the frame shrinks to the room between the margins, down to half its size", "[lecture]") {
  // The frame's scale follows its height (360 rows: half of 720p), so a
  // frame as high and far wider sets the same equation at its full size.
  const std::string equation = "m u'' + b u' + k u + c u^3 = A\\sin(\\omega t) + B\\cos(2\\omega t) + C\\sin(3\\omega t)";
  const double full = scenes::FrameHeading("", equation, 8000, 360).equation_box()->w;
  for (int width : {400, 300, 200}) {
    INFO(width << "x360");
    const double room = width - 2 * 16 * 0.5;  // 16-pixel margins at 720p
    const scenes::FrameHeading heading("", equation, width, 360);
    const render::PixelRect box = *heading.equation_box();
    REQUIRE(full > room);
    CHECK(box.w == Approx(std::max(room, full / 2)).epsilon(0.03));
    CHECK(box.x >= 8 - 1e-9);
    if (full / 2 <= room) CHECK(box.x + box.w <= width - 8 + 1);
  }
  // One that fits keeps its size.
  CHECK(scenes::FrameHeading("", "u'' + u = 0", 640, 360).equation_box()->w ==
        Approx(scenes::FrameHeading("", "u'' + u = 0", 8000, 360).equation_box()->w));
}

TEST_CASE("the equation flag typesets the model's equation, following its settings", "[lecture]") {
  Run r = prepared("pendulum", {{"equation", "true"}, {"alpha", "0"}, {"size", "640x360"}});
  render::Canvas canvas = render::Canvas::image(640, 360);
  r.scene->draw(canvas, r.rows.front());
  bool found = false;
  for (const auto& shape : r.scene->last_layout()->outline.shapes())
    found = found || (shape.kind == render::OutlineKind::formula && shape.name == R"(\theta'' + \sin\theta = 0)");
  CHECK(found);
}

TEST_CASE("comparing schemes with --equation puts each scheme's update formula in the legend", "[lecture]") {
  Run r = prepared("spring", {{"compare", "scheme=forward-euler,crank-nicolson,rk4"}, {"equation", "true"},
                              {"size", "1280x720"}});
  render::Canvas canvas = render::Canvas::image(1280, 720);
  r.scene->draw(canvas, r.rows.front());
  std::vector<std::string> names;
  for (const auto& shape : r.scene->last_layout()->outline.shapes())
    if (shape.kind == render::OutlineKind::formula &&
        (names.empty() || names.back() != shape.name))
      names.push_back(shape.name);
  for (const auto scheme : {Scheme::forward_euler, Scheme::crank_nicolson, Scheme::rk4})
    CHECK(std::find(names.begin(), names.end(), std::string(scheme_info(scheme).formula)) != names.end());
  // At 640x360 the formulas would cover the drawing: the legend keeps the names only.
  Run small = prepared("spring", {{"compare", "scheme=forward-euler,crank-nicolson,rk4"}, {"equation", "true"},
                                  {"size", "640x360"}});
  render::Canvas little = render::Canvas::image(640, 360);
  small.scene->draw(little, small.rows.front());
  for (const auto& shape : small.scene->last_layout()->outline.shapes())
    if (shape.kind == render::OutlineKind::formula) CHECK(shape.name == R"(m u'' + k u = 0)");
  // Without --equation the legend has names only.
  Run plain = prepared("spring", {{"compare", "scheme=forward-euler,rk4"}});
  render::Canvas other = render::Canvas::image(1280, 720);
  plain.scene->draw(other, plain.rows.front());
  for (const auto& shape : plain.scene->last_layout()->outline.shapes())
    CHECK(shape.kind != render::OutlineKind::formula);
}

TEST_CASE("a note is written in the scene's ink on a card of its background, on a dark scene too", "[lecture]") {
  const render::Color ink = render::parse_color("#f2f2f2"), card = render::parse_color("#15151a");
  const scenes::NoteCallouts notes({scenes::parse_note("1-3: the drag $D$ opposes the motion")}, {}, 1280, 720, 10, ink, card);
  const auto requests = notes.body_requests(2, {640, 360});
  REQUIRE(requests.size() == 1);
  const render::TextStyle& style = requests[0].style;
  CHECK(std::tie(style.color.r, style.color.g, style.color.b) == std::tie(ink.r, ink.g, ink.b));
  CHECK(std::tie(style.halo_color.r, style.halo_color.g, style.halo_color.b) == std::tie(card.r, card.g, card.b));
  CHECK(notes.body_requests(4, {640, 360}).empty());  // after its time
}

TEST_CASE("a note shows exactly while its time lasts, and frames drawn one after another equal stills", "[lecture]") {
  Run r = prepared("pendulum", {{"layout", "fbd"}, {"size", "640x360"}, {"periods", "1"}, {"steps_per_period", "40"},
                                {"notes", "1-2: drag takes $\\alpha|\\omega|\\omega$ out"}});
  render::Canvas frames = render::Canvas::image(640, 360);
  frames.track_damage();
  int shown = 0;
  for (size_t k = 0; k < r.rows.size(); k += 2) {
    const double t = r.rows[k][0];
    frames.begin_frame();
    r.scene->draw(frames, r.rows[k]);
    bool has_note = false;
    for (const auto& label : r.scene->last_layout()->placed) {
      if (!label.request.typeset) continue;
      has_note = true;
      CHECK(label.free);  // it covers nothing drawn
    }
    INFO("t = " << t);
    CHECK(has_note == (t >= 1 && t <= 2));
    shown += has_note;
    render::Canvas still = render::Canvas::image(640, 360);
    r.scene->draw(still, r.rows[k]);
    CHECK(same_pixels(frames, still));
  }
  CHECK(shown >= 3);
}

TEST_CASE("a long note beside a diagram covers nothing drawn, at every time and size", "[lecture]") {
  // The lecture example's note: a third of the frame wide, it could only be
  // placed across the pendulum's mg arrow.
  const std::string note = "0-12: the drag D opposes the motion, growing with speed squared";
  for (const std::string scene : {"pendulum", "spring", "sliding_box"}) {
    for (const std::string size : {"1280x720", "640x360"}) {
      Run r = prepared(scene, {{"size", size}, {"periods", "2"}, {"notes", note}});
      const int w = std::stoi(size), h = std::stoi(size.substr(size.find('x') + 1));
      int shown = 0;
      for (size_t k = 0; k < r.rows.size(); k += std::max<size_t>(1, r.rows.size() / 12)) {
        render::Canvas canvas = render::Canvas::image(w, h);
        r.scene->draw(canvas, r.rows[k]);
        for (const auto& label : r.scene->last_layout()->placed) {
          if (!label.request.typeset) continue;
          INFO(scene << " at " << size << ", t = " << r.rows[k][0]);
          CHECK(label.free);
          ++shown;
        }
      }
      CHECK(shown >= 6);
    }
  }
}

TEST_CASE("a note @PANEL goes into that panel with an arrow to its curve", "[lecture]") {
  const std::vector<std::pair<std::string, std::string>> base = {{"size", "1280x720"}, {"periods", "2"}};
  Run plain = prepared("pendulum", base);
  auto with = base;
  with.push_back({"notes", "2-4: the swing shrinks @theta"});
  Run noted = prepared("pendulum", with);
  const size_t k = r_index(noted.rows, 3.0);
  render::Canvas a = render::Canvas::image(1280, 720), b = render::Canvas::image(1280, 720);
  plain.scene->draw(a, plain.rows[k]);
  noted.scene->draw(b, noted.rows[k]);
  const render::PixelRect changed = differing(a, b);
  const render::PixelRect diagram = dynamic_cast<scenes::SystemScene&>(*noted.scene).diagram_area();
  REQUIRE(changed.w > 0);
  CHECK(changed.x >= diagram.x + diagram.w);  // in the panels, right of the diagram
  CHECK(changed.y + changed.h <= 720 / 3.0 + 10);  // in the first panel (theta)
  // By number too; and a panel that is not there is refused, naming those that are.
  CHECK_NOTHROW(prepared("pendulum", {{"notes", "2-4: here @1"}}));
  try {
    prepared("pendulum", {{"notes", "2-4: here @omega"}});
    FAIL("no error");
  } catch (const UsageError& e) {
    CHECK_THAT(e.what(), Catch::Contains("@omega, which is no panel here: choose one of theta, S, D"));
  }
  try {
    prepared("pendulum", {{"layout", "fbd"}, {"notes", "2-4: here @theta"}});
    FAIL("no error");
  } catch (const UsageError& e) {
    CHECK_THAT(e.what(), Catch::Contains("this layout has none"));
  }
}

TEST_CASE("notes are read as T0-T1: TEXT, with @PANEL at the end", "[lecture]") {
  const scenes::Note n = scenes::parse_note("2.5-4: drag takes $\\alpha$ out @theta");
  CHECK(n.from == 2.5);
  CHECK(n.to == 4);
  CHECK(n.text == "drag takes $\\alpha$ out");
  CHECK(n.panel == "theta");
  CHECK(n.shown_at(2.5));
  CHECK(n.shown_at(4));
  CHECK_FALSE(n.shown_at(4.01));
  CHECK(scenes::parse_note("0 - 1 : a").to == 1);
  for (const auto& [spec, expected] : std::vector<std::pair<std::string, std::string>>{
           {"drag takes energy out", "does not start with a time range"},
           {"2-: x", "does not start with a time range"},
           {"a-b: x", "does not start with a time range"},
           {"4-2: backwards", "ends (t = 2) before it starts (t = 4)"},
           {"1-2:   ", "has no text after the colon"},
           {"1-2: text @", "names no panel"},
           {"1-2: $\\foo$", "unknown command \\foo"},
           {"1-2: $x", "never closed"},
       }) {
    INFO(spec);
    try {
      scenes::parse_note(spec);
      FAIL("no error");
    } catch (const UsageError& e) {
      CHECK_THAT(e.what(), Catch::Contains(expected));
      CHECK(std::string(e.what()).find('\n') == std::string::npos);
    }
  }
}

TEST_CASE("scene files take title, equation and a list of notes", "[lecture]") {
  const scenes::SceneConfig c = scenes::parse_scene(
      "model = \"pendulum\"\ntitle = \"The damped pendulum\"\nequation = true\n"
      "notes = [\"1-2: first\", \"3-4: second @S\"]\n",
      "lecture.toml");
  CHECK(c.title == "The damped pendulum");
  CHECK(c.equation);
  CHECK(c.notes == std::vector<std::string>{"1-2: first", "3-4: second @S"});
  try {
    scenes::parse_scene("model = \"pendulum\"\nnotes = [\"4-1: x\"]\n", "lecture.toml");
    FAIL("no error");
  } catch (const UsageError& e) {
    CHECK_THAT(e.what(), Catch::Contains("lecture.toml:2: note"));
  }
  try {
    scenes::parse_scene("model = \"pendulum\"\ntitle = \"$\\\\frac{a}$\"\n", "lecture.toml");
    FAIL("no error");
  } catch (const UsageError& e) {
    CHECK_THAT(e.what(), Catch::Contains("lecture.toml:2: title:"));
  }
}

TEST_CASE("bad titles, equations and notes on the command line: one line, exit 2, nothing written", "[lecture][cli]") {
  test::check_refused("render --note '4-2: backwards' --at 1 -o OUT.png", "before it starts");
  test::check_refused("render --note 'no times' -o OUT.mp4", "does not start with a time range");
  test::check_refused("render --note '1-2: here @nowhere' -o OUT.mp4", "no panel here");
  test::check_refused("render --title '$\\frac{a}$' --at 1 -o OUT.png", "needs an argument");
  test::check_refused("render --title '$x^^2$' -o OUT.mp4", "needs an argument");
  // A long panel name is shown alike where the note is quoted and where the fix says what to drop.
  test::ScratchDirectory dir;
  const auto r = test::run_vibra("render spring --layout fbd --note '1-2: hi @abcdefghijklmnopqrstuvwxyz0123456789' --at 1 -o " +
                                 (dir / "x.png"));
  CHECK(r.exit_code == 2);
  const auto quoted = r.err.find("hi @"), dropped = r.err.find("drop @");
  REQUIRE(quoted != std::string::npos);
  REQUIRE(dropped != std::string::npos);
  const std::string in_note = r.err.substr(quoted + 4, r.err.find("' points", quoted) - quoted - 4);
  const std::string in_fix = r.err.substr(dropped + 6, r.err.find(", or", dropped) - dropped - 6);
  CHECK(in_note == in_fix);
  CHECK(in_note.size() < 36);  // cut short, as every echoed name is
}

TEST_CASE("a still with a title, the equation and a note is written", "[lecture][cli]") {
  test::ScratchDirectory dir;
  const auto r = test::run_vibra("render pendulum --title 'The damped pendulum' --equation --note '1-3: drag' "
                                 "--note '1-3: the swing shrinks @theta' --size 640x360 --at 2 -q -o " +
                                 (dir / "t.png"));
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(test::png_size(dir / "t.png") == std::pair{640, 360});
}
