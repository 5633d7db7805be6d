// The fuzz inputs: each target's bytes turned into a vibra call, shared by the fuzzers and the replay test.
#include "fuzz_inputs.hpp"

#include <glib.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/input/expression.hpp"
#include "core/models/model.hpp"
#include "render/typeset/formula_draw.hpp"
#include "render/typeset/formula_layout.hpp"
#include "render/typeset/formula_parser.hpp"
#include "render/typeset/formula_text.hpp"
#include "scenes/timing/frame_clock.hpp"
#include "scenes/lecture/storyboard.hpp"
#include "scenes/overlays/note.hpp"
#include "scenes/overlays/note_room.hpp"
#include "scenes/config/scene_config.hpp"

namespace vibra::fuzz {
namespace {

// A few steps are enough to run every formula and the time mesh; more would
// only slow the fuzzer down.
constexpr int kSteps = 32;

template <class Body>
void expecting_user_errors(Body body) {
  try {
    body();
  } catch (const UsageError&) {
  } catch (const SolutionError&) {
  }
}

void build_and_step(const ModelDefinition& model, const Parameters& parameters) {
  auto trajectory = model.build(parameters);
  std::vector<double> row(trajectory->width());
  for (int i = 0; i < kSteps && trajectory->advance(); ++i) trajectory->row(row);
}

// Reads every key the way the models do, so each value's parser runs.
void read_every_key(const Parameters& parameters) {
  for (const KeySpec& spec : parameters.specs()) {
    if (!parameters.has_value(spec.name)) continue;
    expecting_user_errors([&] {
      switch (spec.kind) {
        case ValueKind::number: (void)parameters.number(spec.name); break;
        case ValueKind::angle: (void)parameters.angle(spec.name); break;
        case ValueKind::formula: (void)parameters.formula(spec.name); break;
        case ValueKind::choice: (void)parameters.choice(spec.name); break;
        case ValueKind::text: (void)parameters.text(spec.name); break;
      }
    });
  }
}

}  // namespace

void scene_file(std::string_view text) {
  expecting_user_errors([&] {
    const scenes::SceneConfig config = scenes::parse_scene(std::string(text), "fuzz.toml");
    const ModelDefinition& model = find_model(config.model);
    const Parameters parameters = scenes::model_parameters_of(config);
    read_every_key(parameters);
    build_and_step(model, parameters);
    (void)scenes::window_width(config, 1.0);
  });
}

void storyboard(std::string_view text) {
  expecting_user_errors([&] {
    const scenes::Storyboard board = scenes::parse_storyboard(std::string(text), "fuzz.toml");
    for (const scenes::Shot& shot : board.shots) {
      if (shot.is_card) continue;
      expecting_user_errors([&] {
        const Parameters parameters = scenes::model_parameters_of(shot.scene);
        read_every_key(parameters);
        build_and_step(find_model(shot.scene.model), parameters);
        // The pacing against a short run, as the lecture plans it.
        if (!shot.scene.pacing.empty()) (void)scenes::FrameClock::paced(100, shot.scene.fps, 1, shot.scene.pacing);
        // Its notes, and how many a frame shows at once.
        std::vector<scenes::Note> notes;
        for (const std::string& spec : shot.scene.notes) notes.push_back(scenes::parse_note(spec));
        scenes::refuse_crowded_notes(notes, shot.scene.width, shot.scene.height);
      });
    }
  });
}

void set_assignments(std::string_view text) {
  if (text.empty()) return;
  const auto& models = all_models();
  const ModelDefinition& model = models[static_cast<unsigned char>(text[0]) % models.size()];
  text.remove_prefix(1);
  Parameters parameters = model_parameters(model);
  while (!text.empty()) {
    const size_t end = text.find('\n');
    const std::string_view line = text.substr(0, end);
    expecting_user_errors([&] { parameters.assign(line); });
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
  }
  read_every_key(parameters);
  expecting_user_errors([&] { build_and_step(model, parameters); });
}

void expression(std::string_view text) {
  const std::string source(text);
  expecting_user_errors([&] {
    const Expression f("s", source, {"u", "t"});
    const double nan = std::nan(""), inf = HUGE_VAL;
    for (double u : {0.0, -1.5, 1e300, nan})
      for (double t : {0.0, 2.5, -inf}) (void)f({u, t});
  });
  expecting_user_errors([&] { (void)evaluate_constant("dt", source); });
}

void formula(std::string_view text) {
  // One canvas for every input: the fuzzer's time goes into the typesetter.
  static render::Canvas canvas = render::Canvas::image(96, 48);
  expecting_user_errors([&] {
    const render::MathBox box = render::layout_formula(canvas, render::parse_formula(text), {14});
    render::draw_math(canvas, box, {2, 2 + box.ascent}, {});
  });
  expecting_user_errors([&] {
    const render::MathBox box = render::layout_rich_text(canvas, render::parse_rich_text(text), {14}, 60);
    render::draw_math(canvas, box, {2, 2 + box.ascent}, {});
  });
  expecting_user_errors([&] { (void)scenes::parse_note(std::string(text)); });
  // The plain text of subtitles: valid UTF-8 in, valid UTF-8 out.
  expecting_user_errors([&] {
    const std::string plain = render::formula_plain_text(text) + render::rich_text_plain(text);
    if (g_utf8_validate(text.data(), gssize(text.size()), nullptr) &&
        !g_utf8_validate(plain.data(), gssize(plain.size()), nullptr))
      std::abort();
  });
}

}  // namespace vibra::fuzz
