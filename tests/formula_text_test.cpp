// Formulas as plain text (render/typeset/formula_text.hpp): what subtitles,
// chapter titles and a page's captions show where nothing is typeset.
#include <catch2/catch.hpp>
#include <string>

#include "core/error.hpp"
#include "core/models/model.hpp"
#include "core/scheme.hpp"
#include "render/typeset/formula_text.hpp"

using vibra::render::formula_plain_text;
using vibra::render::rich_text_plain;

TEST_CASE("formulas as plain text: primes, scripts, fractions and TeX's spaces", "[typeset]") {
  struct Case {
    const char *source, *text;
  };
  const Case cases[] = {
      {R"(\theta'' + \alpha|\theta'|\theta' + \sin\theta = 0)", "θ″ + α|θ′|θ′ + sin θ = 0"},
      {R"(u'' + \omega^2 u = 0)", "u″ + ω²u = 0"},
      {R"(u^{n+1} = 2u^n - u^{n-1} - \Delta t^2\omega^2 u^n)", "uⁿ⁺¹ = 2uⁿ − uⁿ⁻¹ − Δt²ω²uⁿ"},
      {R"(u_{n+1})", "uₙ₊₁"},
      {R"(x_{q})", "x_q"},
      {R"(e^{-bt})", "e^(−bt)"},
      {R"(\frac{a+b}{2})", "(a + b)/2"},
      {R"(\frac{1}{2}mv^2)", "1/2 mv²"},
      {R"(\Delta t^2 \frac{g}{L}\sin u^n)", "Δt² g/L sin uⁿ"},
      {R"(2\sin\theta)", "2 sin θ"},
      {R"(-x \le y)", "−x ≤ y"},
      {R"(\sqrt{2})", "√2"},
      {R"(\dot{u})", "u\u0307"},
      {R"(\left|u'\right|)", "|u′|"},
      {R"(a \\ b = c)", "a\nb = c"},
  };
  for (const Case& c : cases) {
    INFO(c.source);
    CHECK(formula_plain_text(c.source) == c.text);
  }
}

TEST_CASE("rich text as plain text: words as written, math converted", "[typeset]") {
  CHECK(rich_text_plain("The damped pendulum") == "The damped pendulum");
  CHECK(rich_text_plain(R"(Drag $\alpha|\theta'|\theta'$ takes energy out)") == "Drag α|θ′|θ′ takes energy out");
  CHECK(rich_text_plain(R"(costs \$5)") == "costs $5");
  CHECK_THROWS_AS(rich_text_plain(R"($\frac{a}$)"), vibra::UsageError);
}

TEST_CASE("every model's equation and scheme's formula has a plain text without backslashes", "[typeset]") {
  for (const auto& model : vibra::all_models()) {
    INFO(model.name);
    const std::string text = formula_plain_text(model.equation);
    CHECK(!text.empty());
    CHECK(text.find('\\') == std::string::npos);
  }
  for (const auto& scheme : vibra::all_schemes()) {
    if (scheme.formula.empty()) continue;
    INFO(scheme.name);
    CHECK(formula_plain_text(scheme.formula).find('\\') == std::string::npos);
  }
}
