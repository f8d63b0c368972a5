// Arithmetic expressions of model scripts: numbers, named variables, + - * / ^, parentheses and
// functions. Angles in trigonometric functions are in degrees, as everywhere in Tessera.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace tessera {

class ExprError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct ExprContext {
  // Value of a name; false if unknown.
  std::function<bool(const std::string&, double&)> variable;
  // Value of a function the caller provides (model queries); false if unknown.
  std::function<bool(const std::string&, const std::vector<double>&, double&)> function;
};

// Evaluates an expression; throws ExprError saying what is wrong and where.
double evaluate(const std::string& text, const ExprContext& ctx);

// Splits at commas that are not inside parentheses ("1,(2+3)" -> "1", "(2+3)").
std::vector<std::string> split_top_level(const std::string& text, char sep = ',');

}  // namespace tessera
