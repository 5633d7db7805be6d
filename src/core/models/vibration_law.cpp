#include "core/models/vibration_law.hpp"

#include "core/error.hpp"

namespace vibra {

VibrationLaw VibrationLaw::from(const Parameters& p) {
  VibrationLaw law;
  law.mass = p.positive("m");
  law.b = p.number("b");
  if (law.b < 0) throw UsageError("b=" + p.text("b") + " must be >= 0 (negative damping feeds energy in)");
  const std::string kind = p.choice("damping");
  law.damping = law.b == 0 || kind == "none" ? Damping::none : kind == "linear" ? Damping::linear : Damping::quadratic;
  if (p.given("s") && p.given("k")) throw UsageError("give either k (the linear spring k u) or s (a formula), not both");
  if (p.given("s")) {
    law.s = p.formula("s");
  } else {
    law.k = p.number("k");
    if (!std::isfinite(law.k)) throw UsageError("k=" + p.text("k") + " must be a finite number");
  }
  const Expression F = p.formula("F");
  if (F.text().find_first_not_of(" 0.") != std::string::npos) law.F = F;
  return law;
}

double VibrationLaw::small_oscillation_stiffness() const {
  if (!s) return k;
  const double h = 1e-6;
  return (spring(h) - spring(-h)) / (2 * h);
}

}  // namespace vibra
