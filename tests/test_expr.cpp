// Script arithmetic: precedence, variables, functions in degrees, and errors that say why.
#include <QtTest>

#include "tessera/script/expr.hpp"

using namespace tessera;

class TestExpr : public QObject {
  Q_OBJECT
  ExprContext ctx_;

 private slots:
  void init() {
    ctx_.variable = [](const std::string& n, double& v) {
      if (n == "h") return v = 10, true;
      return false;
    };
  }
  void arithmetic() {
    QCOMPARE(evaluate("2*5", ctx_), 10.0);
    QCOMPARE(evaluate("1+2*3", ctx_), 7.0);
    QCOMPARE(evaluate("(1+2)*3", ctx_), 9.0);
    QCOMPARE(evaluate("-2^2", ctx_), -4.0);
    QCOMPARE(evaluate("2^3^2", ctx_), 512.0);
    QCOMPARE(evaluate("1e10/2", ctx_), 5e9);
    QCOMPARE(evaluate("h/4 + 1", ctx_), 3.5);
  }
  void functionsInDegrees() {
    QVERIFY(std::abs(evaluate("sin(30)", ctx_) - 0.5) < 1e-15);
    QVERIFY(std::abs(evaluate("atan(1)", ctx_) - 45) < 1e-12);
    QCOMPARE(evaluate("max(2, h)", ctx_), 10.0);
    QCOMPARE(evaluate("sqrt(16)", ctx_), 4.0);
  }
  void errorsNameTheProblem() {
    auto message = [&](const char* text) {
      try {
        evaluate(text, ctx_);
      } catch (const ExprError& e) {
        return std::string(e.what());
      }
      return std::string();
    };
    QVERIFY(message("2*hh").find("'hh' is not a defined variable") != std::string::npos);
    QVERIFY(message("(1+2").find("')' is missing") != std::string::npos);
    QVERIFY(message("1/0").find("division by zero") != std::string::npos);
    QVERIFY(message("foo(1)").find("'foo' is not a known function") != std::string::npos);
    QVERIFY(message("2 3").find("unexpected") != std::string::npos);
  }
  void topLevelSplit() {
    const auto p = split_top_level("1,max(2,3)");
    QCOMPARE(p.size(), size_t(2));
    QCOMPARE(p[1], std::string("max(2,3)"));
  }
};

QTEST_APPLESS_MAIN(TestExpr)
#include "test_expr.moc"
