// Expression: a formula the user typed, compiled once by muParser and evaluated many times.
#pragma once
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

namespace vibra {

/// A formula the user typed, such as `sin(u)` or `3*cos(4*t)`, compiled once
/// by muParser and evaluated many times. Knows the constants pi, e and inf.
/// Copies share the compiled form (evaluate from one thread at a time).
class Expression {
 public:
  /// Throws UsageError naming `what` (e.g. "s") when the text does not parse or
  /// uses a variable other than `variables`.
  Expression(std::string what, std::string text, std::vector<std::string> variables);

  /// Evaluates with the variables bound in declaration order.
  double operator()(std::initializer_list<double> values) const;
  double operator()(double x) const { return (*this)({x}); }

  const std::string& text() const;

 private:
  struct Compiled;
  std::shared_ptr<Compiled> compiled_;
};

/// Evaluates a constant expression such as `2*pi/40`; throws UsageError naming `what`.
double evaluate_constant(const std::string& what, const std::string& text);

}  // namespace vibra
