// The forces of the generalized model (1.71) as the vibration model's keys give them.
#include "core/models/vibration_law.hpp"

#include <regex>

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
  law.F = unless_zero(p.formula("F"));
  return law;
}

std::optional<Expression> VibrationLaw::unless_zero(const Expression& F) {
  if (F.text().find_first_not_of(" 0.") == std::string::npos) return std::nullopt;
  return F;
}

std::shared_ptr<SecondOrderSystem<1>> VibrationLaw::system() const {
  std::shared_ptr<SecondOrderSystem<1>> out;
  if (linear_spring() && !F) {
    out = std::make_shared<SecondOrderSystem<1>>(SecondOrderSystem<1>::spring(k / mass));
  } else {
    out = std::make_shared<SecondOrderSystem<1>>(SecondOrderSystem<1>::general(
        [law = *this](const Vec<1>& u, double t) { return Vec<1>((law.external(t) - law.spring(u[0])) / law.mass); }));
  }
  out->damping = damping;
  out->damping_per_mass = b / mass;
  return out;
}

std::function<double(double)> free_linear_solution(const VibrationLaw& law, double I, double V) {
  if (!law.linear_spring() || law.F || !(law.k > 0)) return {};
  const double w = std::sqrt(law.k / law.mass);
  if (law.damping == Damping::none) return [=](double t) { return I * std::cos(w * t) + V / w * std::sin(w * t); };
  if (law.damping != Damping::linear) return {};
  const double zeta = law.b / (2 * std::sqrt(law.k * law.mass));
  if (zeta >= 1) return {};
  const double wd = w * std::sqrt(1 - zeta * zeta);
  return [=](double t) {
    return std::exp(-zeta * w * t) * (I * std::cos(wd * t) + (V + zeta * w * I) / wd * std::sin(wd * t));
  };
}

std::function<double(double)> sine_forced_solution(const VibrationLaw& law, double I, double V) {
  if (!law.linear_spring() || !law.F || law.damping != Damping::none || !(law.k > 0)) return {};
  static const std::regex sine(R"(^\s*(?:(.+?)\s*\*\s*)?sin\s*\(\s*(?:(.+?)\s*\*\s*)?t\s*\)\s*$)");
  std::smatch parts;
  const std::string& text = law.F->text();
  if (!std::regex_match(text, parts, sine)) return {};
  double A = 1, phi = 1;
  try {
    if (parts[1].matched) A = evaluate_constant("F", parts[1].str());
    if (parts[2].matched) phi = evaluate_constant("F", parts[2].str());
  } catch (const UsageError&) {
    return {};  // not constants: some other force
  }
  // The pattern read the text as A sin(phi t): hold the formula to it.
  for (double t : {0.3, 1.7, 2.9})
    if (std::abs((*law.F)(t) - A * std::sin(phi * t)) > 1e-12 * (1 + std::abs(A))) return {};
  const double m = law.mass, w = std::sqrt(law.k / m);
  if (std::abs(phi - w) <= 1e-12 * w) {
    const double c = A / (2 * m * w);
    return [=](double t) { return I * std::cos(w * t) + (V + c) / w * std::sin(w * t) - c * t * std::cos(w * t); };
  }
  const double c = A / (m * (w * w - phi * phi));
  return [=](double t) { return I * std::cos(w * t) + (V - c * phi) / w * std::sin(w * t) + c * std::sin(phi * t); };
}

double VibrationLaw::small_oscillation_stiffness() const {
  if (!s) return k;
  const double h = 1e-6;
  return (spring(h) - spring(-h)) / (2 * h);
}

}  // namespace vibra
