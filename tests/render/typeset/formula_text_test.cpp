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

TEST_CASE("plain text, table-driven: scripts, fractions, function names, Greek letters, primes, asked-for spaces",
          "[typeset]") {
  struct Case {
    const char *kind, *source, *text;
  };
  const Case cases[] = {
      // A space the formula asks for (\, \: \; \quad) reads as one space; \! as none.
      {"space", R"(-\mu\,\mathrm{sign}(u'))", "−μ sign(u′)"},
      {"space", R"(u'' + \mu\,\mathrm{sign}(u') + u = 0)", "u″ + μ sign(u′) + u = 0"},  // the sliding box (1.8.2)
      {"space", R"(u^{n+1} = u^n + \Delta t\, v^n)", "uⁿ⁺¹ = uⁿ + Δt vⁿ"},            // Forward Euler (1.5.x)
      {"space", R"(k_1 = f(y^n),\; k_2)", "k₁ = f(yⁿ), k₂"},
      {"space", R"(a\quad b)", "a b"},
      {"space", R"(a\!b)", "ab"},
      {"subscript", R"(u_{n-1})", "uₙ₋₁"},
      {"subscript", R"(x_i)", "xᵢ"},
      {"subscript", R"(k_{12})", "k₁₂"},
      {"subscript", R"(u_{\theta})", "u_θ"},  // no subscript θ in Unicode: written out
      {"superscript", R"(\omega^2)", "ω²"},
      {"superscript", R"(u^{n})", "uⁿ"},
      {"superscript", R"(e^{i\omega t})", "e^(iωt)"},
      {"fraction", R"(\frac{g}{L})", "g/L"},
      {"fraction", R"(\frac{1 - 2\lambda}{2})", "(1 − 2λ)/2"},
      {"fraction", R"(\frac{\tanh(\alpha u)}{\alpha})", "tanh(αu)/α"},
      {"function", R"(\sin\theta)", "sin θ"},
      {"function", R"(\cos(\omega t))", "cos(ωt)"},
      {"function", R"(\exp x)", "exp x"},
      {"greek", R"(\alpha\beta\gamma)", "αβγ"},
      {"greek", R"(\Delta\Theta\Omega)", "ΔΘΩ"},
      {"prime", R"(u')", "u′"},
      {"prime", R"(\theta'')", "θ″"},
      {"prime", R"(u''')", "u‴"},
      {"prime", R"(u'^2)", "u′²"},
  };
  for (const Case& c : cases) {
    INFO(c.kind << ": " << c.source);
    CHECK(formula_plain_text(c.source) == c.text);
  }
  // And inside rich text, as subtitles and legends show it.
  CHECK(rich_text_plain(R"(friction $-\mu\,\mathrm{sign}(u')$ opposes the motion)") ==
        "friction −μ sign(u′) opposes the motion");
}

TEST_CASE("plain text: every character Unicode has as a sub- or superscript, each to its own", "[typeset]") {
  // The characters, typed from Unicode's Superscripts and Subscripts block
  // (U+2070-U+209C) and the phonetic letters (U+1D62-U+1D65, U+2C7C, U+2071):
  // a typo in one entry of the table maps one script to a wrong character.
  struct Case {
    const char *source, *text;
  };
  const Case cases[] = {
      {R"(x_{0123456789})", "x₀₁₂₃₄₅₆₇₈₉"},
      {R"(x_{+})", "x₊"}, {R"(x_{-})", "x₋"}, {R"(x_{=})", "x₌"}, {R"(x_{(n)})", "x₍ₙ₎"},
      {R"(x_{aeoxhklm})", "xₐₑₒₓₕₖₗₘ"},
      {R"(x_{npstijruv})", "xₙₚₛₜᵢⱼᵣᵤᵥ"},
      {R"(x^{0123456789})", "x⁰¹²³⁴⁵⁶⁷⁸⁹"},
      {R"(x^{+})", "x⁺"}, {R"(x^{-})", "x⁻"}, {R"(x^{=})", "x⁼"}, {R"(x^{(n)})", "x⁽ⁿ⁾"}, {R"(x^{i})", "xⁱ"},
      {R"(x_{b})", "x_b"},  // no subscript b: written out
      {R"(x^{k})", "x^k"},  // no superscript k in the table: written out
  };
  for (const Case& c : cases) {
    INFO(c.source);
    CHECK(formula_plain_text(c.source) == c.text);
  }
}
