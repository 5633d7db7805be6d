// Expression: a formula the user typed, compiled once by muParser and evaluated many times.
#include "core/input/expression.hpp"

#include <muParser.h>

#include <array>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/input/quoted_value.hpp"

namespace vibra {

struct Expression::Compiled {
  mu::Parser parser;
  std::array<double, 4> values{};
  std::string text;
};

namespace {
void define_constants(mu::Parser& parser) {
  parser.DefineConst("pi", M_PI);
  parser.DefineConst("e", M_E);
  parser.DefineConst("inf", std::numeric_limits<double>::infinity());
}

std::string one_line(std::string message) {
  for (char& c : message)
    if (c == '\n') c = ' ';
  return message;
}
}  // namespace

Expression::Expression(std::string what, std::string text, std::vector<std::string> variables)
    : compiled_(std::make_shared<Compiled>()) {
  if (variables.size() > compiled_->values.size()) throw std::logic_error("too many expression variables");
  compiled_->text = text;
  std::string names;
  try {
    define_constants(compiled_->parser);
    for (size_t i = 0; i < variables.size(); ++i) {
      compiled_->parser.DefineVar(variables[i], &compiled_->values[i]);
      names += (i ? ", " : "") + variables[i];
    }
    compiled_->parser.SetExpr(text);
    compiled_->parser.Eval();  // compiles now, so errors surface at startup
  } catch (const mu::Parser::exception_type& e) {
    throw UsageError("cannot read " + what + "='" + quoted_value(text) + "': " + quoted_value(one_line(e.GetMsg()), 80) +
                     " (write a formula in " + (names.empty() ? "numbers" : names) +
                     ", e.g. sin(u) or 3*cos(4*t))");
  }
}

double Expression::operator()(std::initializer_list<double> values) const {
  std::copy(values.begin(), values.end(), compiled_->values.begin());
  return compiled_->parser.Eval();
}

const std::string& Expression::text() const { return compiled_->text; }

double evaluate_constant(const std::string& what, const std::string& text) {
  if (text.find_first_not_of(" \t") == std::string::npos)
    throw UsageError("empty value for " + what + ": give a number, e.g. " + what + "=0.5");
  // What people try that is not an expression here: say how to write it.
  const std::string fix = " (write a decimal number or an expression of numbers, pi, e and inf, e.g. 0.5, 1e-3 or 2*pi/40)";
  mu::Parser parser;
  try {
    define_constants(parser);
    parser.SetExpr(text);
    double value = parser.Eval();
    if (std::isnan(value)) throw UsageError("value of " + what + "='" + quoted_value(text) + "' is not a number" + fix);
    return value;
  } catch (const mu::Parser::exception_type& e) {
    throw UsageError("cannot read " + what + "='" + quoted_value(text) + "' as a number: " +
                     quoted_value(one_line(e.GetMsg()), 60) + fix);
  }
}

}  // namespace vibra
