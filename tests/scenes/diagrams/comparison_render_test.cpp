// `vibra render --compare KEY=V1,V2,...`: the members as one trajectory of
// wide rows (each exact at its own samples), ghosts drawn where their runs
// are, blow-ups noted, bad input refused.
#include <catch2/catch.hpp>

#include <cairo.h>

#include <cmath>
#include <cstring>
#include <iterator>
#include <fstream>
#include <map>
#include <set>

#include "cli_support.hpp"
#include "core/comparison_trajectory.hpp"
#include "render/draw/canvas.hpp"
#include "scenes/diagrams/comparison_labels.hpp"
#include "scenes/diagrams/pendulum/pendulum_geometry.hpp"
#include "scenes/overlays/run_legend.hpp"
#include "scenes/config/scene_config.hpp"
#include "scenes/scene_factory.hpp"
#include "scenes/system_scene.hpp"
#include "test_support.hpp"

using namespace vibra;
using test::check_refused;
using test::run_vibra;
using test::ScratchDirectory;

namespace {

/// Every sample of a member run alone: time -> row.
std::map<double, std::vector<double>> samples(const std::string& model, const Parameters& p) {
  auto run = find_model(model).build(p);
  std::map<double, std::vector<double>> out;
  do {
    std::vector<double> row(run->width());
    run->row(row);
    out[row[0]] = row;
  } while (run->advance());
  return out;
}

std::string frame_count(const std::string& video) {
  return test::shell("ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 '" +
                     video + "'");
}

/// A scene after its pre-pass, drawn at t = 0 on a canvas of its size.
struct DrawnScene {
  std::unique_ptr<scenes::Scene> scene;
  render::Canvas canvas;
  std::vector<double> row;
  render::WorldView view() const { return dynamic_cast<scenes::SystemScene&>(*scene).view_at(row); }
  /// The canvas's pixel at p: r, g, b.
  std::array<int, 3> pixel(const render::Point& p) const {
    const unsigned char* px = canvas.data() + int(p.y()) * canvas.stride() + 4 * int(p.x());
    return {px[2], px[1], px[0]};
  }
};
DrawnScene drawn_at_start(const std::string& name, const std::vector<std::pair<std::string, std::string>>& settings) {
  scenes::SceneConfig config = scenes::load_scene(name);
  for (const auto& [k, v] : settings) scenes::apply_setting(config, {k, v, "test"});
  auto pre_pass = scenes::build_scene_runs(config);
  DrawnScene d{scenes::make_scene_for(config, *pre_pass, "test"), render::Canvas::image(config.width, config.height),
               std::vector<double>(pre_pass->width())};
  do {
    pre_pass->row(d.row);
    d.scene->record(d.row);
  } while (pre_pass->advance());
  scenes::build_scene_runs(config)->row(d.row);
  d.scene->draw(d.canvas, d.row);
  d.canvas.flush();
  return d;
}
}  // namespace

TEST_CASE("a comparison's rows hold every member exactly at its own samples, on the union of their meshes",
          "[comparison]") {
  const Parameters base = model_settings("undamped", {"w=1", "T=3", "scheme=crank-nicolson"});
  ComparisonTrajectory runs(find_model("undamped"), base, parse_comparison("dt=0.1,0.15"));
  REQUIRE(runs.members() == 2);
  CHECK(runs.info().columns == std::vector<std::string>{"t", "u[dt=0.1]", "v[dt=0.1]", "u[dt=0.15]", "v[dt=0.15]"});
  CHECK(runs.info().mesh.dt == 0.1);
  REQUIRE(runs.info().exact);  // one problem solved twice: one exact solution

  std::vector<std::map<double, std::vector<double>>> alone;
  std::set<double> union_of_meshes;
  for (const char* dt : {"dt=0.1", "dt=0.15"}) {
    Parameters p = base;
    p.assign(dt);
    alone.push_back(samples("undamped", p));
    for (const auto& [t, row] : alone.back()) union_of_meshes.insert(t);
  }
  std::vector<double> times, row(runs.width());
  do {
    runs.row(row);
    times.push_back(row[0]);
    for (size_t i = 0; i < 2; ++i) {
      INFO("member " << i << " at t = " << row[0]);
      const auto own = alone[i].find(row[0]);
      if (own != alone[i].end()) {  // its own sample: exactly its numbers
        CHECK(row[runs.offset(i)] == own->second[1]);
        CHECK(row[runs.offset(i) + 1] == own->second[2]);
      } else {  // between its samples: on the straight line between its two neighbours
        const auto after = alone[i].upper_bound(row[0]);
        REQUIRE(after != alone[i].begin());
        REQUIRE(after != alone[i].end());
        const auto before = std::prev(after);
        const double s = (row[0] - before->first) / (after->first - before->first);
        CHECK(row[runs.offset(i)] == Approx(before->second[1] + s * (after->second[1] - before->second[1])).margin(1e-12));
        CHECK(row[runs.offset(i) + 1] == Approx(before->second[2] + s * (after->second[2] - before->second[2])).margin(1e-12));
      }
    }
  } while (runs.advance());
  CHECK(runs.done());
  CHECK(times == std::vector<double>(union_of_meshes.begin(), union_of_meshes.end()));
}

TEST_CASE("a member that blows up reads NaN from then on while the others run to the end", "[comparison]") {
  const Parameters base = model_settings("undamped", {"steps_per_period=8", "periods=6"});
  ComparisonTrajectory runs(find_model("undamped"), base, parse_comparison("scheme=forward-euler,crank-nicolson"));
  std::vector<double> row(runs.width());
  double last_t = 0;
  do {
    runs.row(row);
    last_t = row[0];
    const bool gone = row[0] >= runs.blow_up_time(0);
    CHECK(std::isnan(row[runs.offset(0)]) == gone);
    CHECK(std::isfinite(row[runs.offset(1)]));
    if (!gone) CHECK(std::abs(row[runs.offset(0)]) <= runs.comparison().escape_limit(0));
  } while (runs.advance());
  CHECK(runs.blow_up_time(0) < 6);  // Forward Euler's amplitude grows by 27% a step here
  CHECK((*runs.early_ends())[0] == EarlyEnd::left_view);  // still finite: it left the view
  CHECK((*runs.early_ends())[1] == EarlyEnd::none);
  CHECK(std::isinf(runs.blow_up_time(1)));
  CHECK(last_t == Approx(6).epsilon(1e-12));
}

TEST_CASE("the legend learns when each run ended from the rows, and why", "[comparison]") {
  EarlyEnd why_a = EarlyEnd::none;
  scenes::RunLegend legend({{"a", render::palette::blue, false, [](std::span<const double> r) { return r[1]; },
                             [&] { return why_a; }},
                            {"b", render::palette::orange, false, [](std::span<const double> r) { return r[2]; }},
                            {"exact", render::palette::ink, true}},
                           360);
  CHECK(legend.width() > 0);
  for (double t : {0.0, 1.0, 2.0, 3.0}) {
    if (t == 2) why_a = EarlyEnd::left_view;  // as the trajectory learns it, before its rows turn NaN
    const double row[] = {t, t < 2 ? 1.0 : NAN, 1.0};
    legend.record(row);
  }
  CHECK(legend.blow_up_time(0) == 2);
  CHECK(legend.early_end(0) == EarlyEnd::left_view);
  CHECK(std::isinf(legend.blow_up_time(1)));
  CHECK(std::isinf(legend.blow_up_time(2)));
  CHECK(scenes::early_end_note(EarlyEnd::left_view, 2) == "left the view at <i>t</i> = 2");
  CHECK(scenes::early_end_note(EarlyEnd::blew_up, 2) == "blew up at <i>t</i> = 2");
}

TEST_CASE("a run that stays bounded stays in view: one that grows leaves it, one that overflows blew up", "[comparison]") {
  // Euler-Cromer at a dt near its stability limit swings to |u| = 2.3 from
  // u(0) = 1 and decays: bounded, so the view holds it.
  const Parameters wide = model_settings("vibration", {"m=4", "damping=quadratic", "b=0.2", "s=2*u",
                                                 "dt=0.9*2/sqrt(0.5)", "periods=6"});
  ComparisonTrajectory bounded(find_model("vibration"), wide, parse_comparison("scheme=centered,euler-cromer"));
  while (bounded.advance()) {
  }
  CHECK(std::isinf(bounded.blow_up_time(0)));
  CHECK(std::isinf(bounded.blow_up_time(1)));
  // Forward Euler gains energy every step: past 4 times its first swing it leaves, still finite.
  Comparison growing(find_model("undamped"), model_settings("undamped", {"steps_per_period=8", "periods=40"}),
                     parse_comparison("scheme=forward-euler,rk4"));
  growing.set_view_limits();
  growing.advance_to(growing.end_time());
  CHECK(growing.early_end(0) == EarlyEnd::left_view);
  CHECK(growing.early_end(1) == EarlyEnd::none);
  // Without a view limit, it runs until its values overflow: that is a blow-up.
  Comparison overflowing(find_model("undamped"), model_settings("undamped", {"steps_per_period=8", "periods=4000"}),
                         parse_comparison("scheme=forward-euler,rk4"));
  overflowing.advance_to(overflowing.end_time());
  CHECK(overflowing.early_end(0) == EarlyEnd::blew_up);
  CHECK(overflowing.early_end(1) == EarlyEnd::none);
}

TEST_CASE("a run whose swings end three times as wide as they start leaves the view, the calm one has no limit",
          "[comparison]") {
  // Forward Euler multiplies the amplitude by sqrt(1 + (w dt)^2) a step: at
  // 100 steps a period over 7 periods, the largest swing of the last quarter
  // is about that factor to the 525th power (three quarters of the 700
  // steps) times the first quarter's: 2.8, over the twice that marks growth
  // without bound, and Crank-Nicolson keeps |u| <= 1 (growth 1).
  const double growth = std::pow(1 + std::pow(2 * M_PI / 100, 2), 0.5 * 525);
  REQUIRE(growth > 2.5);
  REQUIRE(growth < 3.2);
  Comparison c(find_model("undamped"), model_settings("undamped", {"steps_per_period=100", "periods=7"}),
               parse_comparison("scheme=forward-euler,crank-nicolson"));
  c.set_view_limits();
  // It leaves at twice the largest |u| of the bounded runs and of what energy allows: 2 I.
  CHECK(c.escape_limit(0) == Approx(2.0).epsilon(1e-6));
  CHECK(std::isinf(c.escape_limit(1)));
}

TEST_CASE("each member's ghost is drawn at its own state", "[comparison]") {
  // t = 0: the bobs at 10 and 60 degrees.
  const DrawnScene d = drawn_at_start("pendulum", {{"compare", "Theta=10,60"}, {"layout", "fbd"}, {"alpha", "0"},
                                                   {"size", "640x360"}});
  const render::WorldView view = d.view();
  // A few pixels right of the bob's centre: its forces start at the centre
  // and point down (mg) and up the wire, to the left.
  auto pixel_at = [&](double degrees) {
    return d.pixel(view.to_pixel(scenes::pendulum_geometry({0, degrees * M_PI / 180, 0, 1, 0}, {}).bob) +
                   render::Point(4, 0));
  };
  const auto first = pixel_at(10), ghost = pixel_at(60), nothing = pixel_at(-60);
  INFO("first " << first[0] << "," << first[1] << "," << first[2] << "  ghost " << ghost[0] << "," << ghost[1] << ","
                << ghost[2]);
  CHECK(first[2] > first[0] + 80);  // the first run's bob: solid blue
  CHECK(ghost[0] > ghost[2] + 60);  // the ghost's bob: faint orange
  CHECK(ghost[0] < 250);
  CHECK(nothing == std::array<int, 3>{255, 255, 255});
}

TEST_CASE("ghosts that moved far since the frame before are drawn whole, as on a canvas that drew nothing before",
          "[comparison]") {
  // The ghosts' group covers where they were in the frame before, with a
  // margin: a ghost beyond it is drawn again in a group of the whole diagram.
  const std::vector<std::pair<std::string, std::string>> settings = {
      {"compare", "scheme=forward-euler,backward-euler,rk4"}, {"layout", "fbd"}, {"size", "640x360"}};
  DrawnScene moved = drawn_at_start("spring", settings);  // drew t = 0
  DrawnScene fresh = drawn_at_start("spring", settings);
  scenes::SceneConfig config = scenes::load_scene("spring");
  for (const auto& [k, v] : settings) scenes::apply_setting(config, {k, v, "test"});
  auto runs = scenes::build_scene_runs(config);
  std::vector<double> row(runs->width()), half_period;
  do {
    runs->row(row);
    if (half_period.empty() && row[0] >= M_PI - 1e-9) half_period = row;  // u from 1 to about -1
  } while (row[0] < 2 * M_PI - 1e-9 && runs->advance());  // and back
  REQUIRE(!half_period.empty());
  // The ghosts' box runs from the wall to the bodies: it shrinks by half a
  // period, and grows back beyond the margin (24 px at 360p) by a period.
  REQUIRE(std::abs(row[1] - half_period[1]) * moved.view().zoom() > 60);
  // The same frame drawn after the others and drawn first (new label chains: no spots remembered).
  moved.scene->draw(moved.canvas, half_period);
  moved.scene->set_label_chain(1);
  moved.scene->draw(moved.canvas, row);
  moved.canvas.flush();
  render::Canvas first = render::Canvas::image(config.width, config.height);
  fresh.scene->set_label_chain(1);
  fresh.scene->draw(first, row);
  first.flush();
  int differ = 0;
  for (int y = 0; y < config.height; ++y)
    differ += std::memcmp(moved.canvas.data() + y * moved.canvas.stride(), first.data() + y * first.stride(),
                          4 * size_t(config.width)) != 0;
  CHECK(differ == 0);
}

TEST_CASE("in a comparison the first run's forces are charcoal: a hue names a run", "[comparison]") {
  // t = 0: the first bob at 10 degrees, its weight mg straight down from it.
  for (const char* compare : {"Theta=10,60", "scheme=rk4,forward-euler,crank-nicolson,euler-cromer"}) {
    const DrawnScene d =
        drawn_at_start("pendulum", {{"Theta", "10"}, {"compare", compare}, {"layout", "fbd"}, {"size", "640x360"}});
    const render::Point bob =
        d.view().to_pixel(scenes::pendulum_geometry({0, 10 * M_PI / 180, 0, 1, 0}, {}).bob);
    // Below the bob's rim, where mg's shaft runs (forces start at the rim).
    const auto on_weight = d.pixel(bob + render::Point(0, 24));
    INFO(compare << ": " << on_weight[0] << "," << on_weight[1] << "," << on_weight[2]);
    const render::Color c = render::palette::charcoal;
    CHECK(std::abs(on_weight[0] - int(255 * c.r)) <= 12);
    CHECK(std::abs(on_weight[1] - int(255 * c.g)) <= 12);
    CHECK(std::abs(on_weight[2] - int(255 * c.b)) <= 12);
  }
  // Colours a scene file gives the forces are kept.
  const DrawnScene own = drawn_at_start("pendulum", {{"compare", "Theta=10,60"}, {"layout", "fbd"}, {"size", "640x360"},
                                                      {"colors.gravity", "#00ff00"}});
  const render::Point bob = own.view().to_pixel(scenes::pendulum_geometry({0, 10 * M_PI / 180, 0, 1, 0}, {}).bob);
  const auto on_weight = own.pixel(bob + render::Point(0, 24));
  CHECK(on_weight[1] > on_weight[0] + 150);
}

TEST_CASE("render --compare writes a video of the run's frames, from the flag or a scene file", "[comparison][cli]") {
  ScratchDirectory dir;
  const std::string common = " --set periods=1 --size 320x180 -q -o ";
  REQUIRE(run_vibra("render spring" + common + dir / "one.mp4").exit_code == 0);
  const auto compared = run_vibra("render spring --compare scheme=forward-euler,rk4" + common + dir / "two.mp4");
  INFO(compared.err);
  REQUIRE(compared.exit_code == 0);
  CHECK(frame_count(dir / "two.mp4") == frame_count(dir / "one.mp4"));

  // A scene file's scheme gives way to the comparison's.
  std::ofstream(dir / "schemes.toml") << "model = \"undamped\"\nscheme = \"rk4\"\ncompare = \"scheme=forward-euler,rk4\"\n"
                                         "layout = \"grid\"\nperiods = 2\n";
  const auto grid = run_vibra("render " + dir / "schemes.toml --at 1.5 -o " + dir / "grid.png");
  INFO(grid.err);
  CHECK(grid.exit_code == 0);
  CHECK(std::filesystem::exists(dir / "grid.png"));
}

TEST_CASE("render --compare refuses bad input with one line and writes nothing", "[comparison][cli]") {
  check_refused("render spring --compare scheme=rk4,rk4 -o OUT.mp4", "scheme=rk4 is given twice");
  check_refused("render spring --compare kk=1,2 -o OUT.mp4", "did you mean 'k'");
  check_refused("render spring --compare dt=1,2,3,4,5,6,7,8,9 -o OUT.mp4", "at most 8");
  check_refused("render spring --set scheme=rk4 --compare scheme=rk4,pefrl -o OUT.mp4", "drop --set scheme");
  check_refused("render spring --layout grid -o OUT.mp4", "add --compare");
  check_refused("render spring --compare scheme -o OUT.mp4", "not KEY=V1,V2");
}

TEST_CASE("ghosts on top of each other and of the first run all show, each in its colour", "[comparison]") {
  // At t = 0 every scheme's bob is at Theta: three runs in one place.
  const DrawnScene d = drawn_at_start("pendulum", {{"compare", "scheme=rk4,crank-nicolson,euler-cromer"},
                                                   {"layout", "fbd"}, {"size", "1280x720"}});
  const render::WorldView view = d.view();
  const scenes::PendulumGeometry g = scenes::pendulum_geometry({0, d.row[1], 0, 1, 0}, {});
  const render::Point bob = view.to_pixel(g.bob);
  const double radius = scenes::PendulumDiagramOptions{}.bob_radius * view.zoom();
  // Pixels of a colour, at full strength, within a few pixels of the bob's
  // edge, away from where the arrows mg (down) and S (to the pivot) leave it:
  // their colours are among the members'.
  const render::Point down(0, 1), to_pivot = (view.to_pixel(g.pivot) - bob).normalized();
  auto on_rim = [&](const render::Color& c) {
    int n = 0;
    for (int y = int(bob.y() - radius - 6); y <= int(bob.y() + radius + 6); ++y)
      for (int x = int(bob.x() - radius - 6); x <= int(bob.x() + radius + 6); ++x) {
        const render::Point p(x + 0.5 - bob.x(), y + 0.5 - bob.y());
        if (std::abs(p.norm() - radius) > 4) continue;
        if (p.normalized().dot(down) > 0.8 || p.normalized().dot(to_pivot) > 0.8) continue;
        const auto px = d.pixel({double(x), double(y)});
        n += std::abs(px[0] - c.r * 255) < 40 && std::abs(px[1] - c.g * 255) < 40 && std::abs(px[2] - c.b * 255) < 40;
      }
    return n;
  };
  const scenes::SceneConfig config = scenes::load_scene("pendulum");
  for (size_t member = 1; member < 3; ++member) {
    INFO("member " << member);
    CHECK(on_rim(scenes::member_color(config.colors.bob, member)) > 15);
  }
}

TEST_CASE("a comparison's diagram is drawn as large as one run's: the legend goes above a wide drawing",
          "[comparison]") {
  struct Case {
    std::string scene, compare, alone;
  };
  for (const Case& c : {Case{"pendulum", "Theta=40,60", "Theta=60"}, Case{"spring", "scheme=rk4,crank-nicolson", ""}}) {
    INFO(c.scene << " --compare " << c.compare);
    std::vector<std::pair<std::string, std::string>> alone;
    if (!c.alone.empty()) alone.push_back({c.alone.substr(0, c.alone.find('=')), c.alone.substr(c.alone.find('=') + 1)});
    const DrawnScene one = drawn_at_start(c.scene, alone);
    const DrawnScene both = drawn_at_start(c.scene, {{"compare", c.compare}});
    CHECK(both.view().zoom() >= 0.9 * one.view().zoom());
    // The legend covers none of the drawing.
    const auto& shapes = both.scene->last_layout()->outline.shapes();
    for (const auto& legend : shapes) {
      if (legend.kind != render::OutlineKind::legend) continue;
      for (const auto& shape : shapes)
        if (shape.kind == render::OutlineKind::body || shape.kind == render::OutlineKind::spring ||
            shape.kind == render::OutlineKind::wire || shape.kind == render::OutlineKind::arrow ||
            shape.kind == render::OutlineKind::ground) {
          INFO("a legend shape at " << legend.bounds.x << ", " << legend.bounds.y << " and a " << outline_kind_name(shape.kind));
          CHECK_FALSE(render::overlaps(legend.bounds, shape));
        }
    }
  }
}
