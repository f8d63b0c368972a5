// Recursive-descent evaluation of script expressions.
#include "tessera/script/expr.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <numbers>

#include "tessera/core/angles.hpp"

namespace tessera {

namespace {

class Parser {
 public:
  Parser(const std::string& s, const ExprContext& ctx) : s_(s), ctx_(ctx) {}

  double parse() {
    const double v = sum();
    skip();
    if (pos_ < s_.size()) fail("unexpected '" + std::string(1, s_[pos_]) + "'");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    // A long expression is quoted by its start only.
    const std::string shown = s_.size() > 80 ? s_.substr(0, 60) + "..." : s_;
    throw ExprError("cannot read the number '" + shown + "': " + why);
  }
  void skip() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  bool eat(char c) {
    skip();
    if (pos_ < s_.size() && s_[pos_] == c) return ++pos_, true;
    return false;
  }
  double sum() {
    double v = product();
    for (;;) {
      if (eat('+'))
        v += product();
      else if (eat('-'))
        v -= product();
      else
        return v;
    }
  }
  double product() {
    double v = unary();
    for (;;) {
      if (eat('*')) {
        v *= unary();
      } else if (eat('/')) {
        const double d = unary();
        if (d == 0.0) fail("division by zero");
        v /= d;
      } else {
        return v;
      }
    }
  }
  // Nesting (parentheses, signs, calls) is bounded: each level is a frame of the C++ stack.
  static constexpr int kMaxDepth = 200;
  struct Nest {
    Parser& p;
    explicit Nest(Parser& parser) : p(parser) {
      if (++p.depth_ > kMaxDepth)
        p.fail("it nests more than " + std::to_string(kMaxDepth) +
               " levels deep (parentheses, signs or calls)");
    }
    ~Nest() { --p.depth_; }
  };
  double unary() {
    const Nest nest(*this);
    if (eat('-')) return -unary();
    if (eat('+')) return unary();
    return power();
  }
  double power() {
    const double base = primary();
    if (eat('^')) return std::pow(base, unary());
    return base;
  }
  double primary() {
    skip();
    if (pos_ >= s_.size()) fail("it ends too early");
    if (eat('(')) {
      const double v = sum();
      if (!eat(')')) fail("a ')' is missing");
      return v;
    }
    const char c = s_[pos_];
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      const char* begin = s_.c_str() + pos_;
      char* end = nullptr;
      const double v = std::strtod(begin, &end);
      if (end == begin) fail("bad number");
      pos_ += static_cast<size_t>(end - begin);
      return v;
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      const size_t start = pos_;
      while (pos_ < s_.size() &&
             (std::isalnum(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_'))
        ++pos_;
      const std::string name = s_.substr(start, pos_ - start);
      if (eat('(')) return call(name, arguments());
      return variable(name);
    }
    fail("unexpected '" + std::string(1, c) + "'");
  }
  std::vector<double> arguments() {
    std::vector<double> args;
    if (eat(')')) return args;
    do args.push_back(sum());
    while (eat(','));
    if (!eat(')')) fail("a ')' is missing");
    return args;
  }
  double variable(const std::string& name) {
    if (name == "pi") return std::numbers::pi;
    double v = 0.0;
    if (ctx_.variable && ctx_.variable(name, v)) return v;
    fail("'" + name + "' is not a defined variable (define it with 'set " + name + " = ...')");
  }
  double call(const std::string& f, const std::vector<double>& a) {
    auto need = [&](size_t n) {
      if (a.size() != n) fail(f + "() takes " + std::to_string(n) + " argument(s)");
    };
    if (f == "sin") return need(1), std::sin(a[0] * kDeg);
    if (f == "cos") return need(1), std::cos(a[0] * kDeg);
    if (f == "tan") return need(1), std::tan(a[0] * kDeg);
    if (f == "asin") return need(1), std::asin(a[0]) / kDeg;
    if (f == "acos") return need(1), std::acos(a[0]) / kDeg;
    if (f == "atan") return need(1), std::atan(a[0]) / kDeg;
    if (f == "atan2") return need(2), std::atan2(a[0], a[1]) / kDeg;
    if (f == "sqrt") {
      need(1);
      if (a[0] < 0.0) fail("sqrt of a negative number");
      return std::sqrt(a[0]);
    }
    if (f == "abs") return need(1), std::abs(a[0]);
    if (f == "exp") return need(1), std::exp(a[0]);
    if (f == "log") return need(1), std::log(a[0]);
    if (f == "log10") return need(1), std::log10(a[0]);
    if (f == "floor") return need(1), std::floor(a[0]);
    if (f == "ceil") return need(1), std::ceil(a[0]);
    if (f == "min") return need(2), std::min(a[0], a[1]);
    if (f == "max") return need(2), std::max(a[0], a[1]);
    double v = 0.0;
    if (ctx_.function && ctx_.function(f, a, v)) return v;
    fail("'" + f + "' is not a known function");
  }

  const std::string& s_;
  const ExprContext& ctx_;
  size_t pos_ = 0;
  int depth_ = 0;
};

}  // namespace

double evaluate(const std::string& text, const ExprContext& ctx) {
  const double v = Parser(text, ctx).parse();
  if (!std::isfinite(v)) throw ExprError("the number '" + text + "' is not finite");
  return v;
}

std::vector<std::string> split_top_level(const std::string& text, char sep) {
  std::vector<std::string> parts(1);
  int depth = 0;
  for (char c : text) {
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if (c == sep && depth == 0) {
      parts.emplace_back();
      continue;
    }
    parts.back() += c;
  }
  return parts;
}

}  // namespace tessera
