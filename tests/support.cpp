#include "support.hpp"

#include <Eigen/Dense>
#include <QMetaMethod>
#include <QTest>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <vector>

namespace tessera::test {

ScriptRun::ScriptRun()
    : interp(std::make_unique<Interpreter>(
          dir.path().toStdString(), [this](const std::string& line) { log += line + "\n"; })) {}

void ScriptRun::run(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  int n = 0;
  while (std::getline(in, line)) interp->execute(line, "test", ++n);
}

std::string ScriptRun::path(const std::string& name) const {
  return dir.path().toStdString() + "/" + name;
}

std::string incline_script(double psi, double phi, double b, double h, double kn) {
  return "set psi = " + std::to_string(psi) + "\nset phi = " + std::to_string(phi) +
         "\nset b = " + std::to_string(b) + "\nset h = " + std::to_string(h) +
         "\nset c = cos(psi)\nset s = sin(psi)\n"
         "round 0.005\n"
         "material define rock density=2500\n"
         "joint define j kn=" +
         std::to_string(kn) + " ks=" + std::to_string(kn) +
         " friction=phi\n"
         "joint assign j\n"
         "block (-8*c+s),(-8*s-c) (4*c+s),(4*s-c) 4*c,4*s (-8*c),(-8*s) group=base material=rock\n"
         "block 0,0 b*c,b*s (b*c-h*s),(b*s+h*c) (-h*s),h*c material=rock\n"
         "fix group=base\n"
         "gravity 0 -9.81\n";
}

namespace {
void mix(uint64_t& h, const void* data, size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 1099511628211ULL;
}
template <class T>
void mix_vec(uint64_t& h, const std::vector<T>& v) {
  for (const T& x : v) mix(h, &x, sizeof x);
}
}  // namespace

uint64_t state_hash(const Model& m) {
  uint64_t h = 1469598103934665603ULL;
  const Blocks& B = m.blocks;
  for (auto* v : {&B.x, &B.y, &B.theta, &B.vx, &B.vy, &B.omega}) mix_vec(h, *v);
  const Contacts& C = m.contacts;
  mix_vec(h, C.fn), mix_vec(h, C.fs), mix_vec(h, C.a), mix_vec(h, C.corner);
  const Continuum& Z = m.continuum;
  mix_vec(h, Z.pos), mix_vec(h, Z.vel), mix_vec(h, Z.stress), mix_vec(h, Z.state);
  const Continuum3& Z3 = m.continuum3;
  mix_vec(h, Z3.pos), mix_vec(h, Z3.vel), mix_vec(h, Z3.stress), mix_vec(h, Z3.state);
  for (const RigidBody3& b : m.blocks3.body)
    mix(h, b.position.data(), 24), mix(h, b.velocity.data(), 24), mix(h, b.momentum.data(), 24),
        mix(h, b.orientation.coeffs().data(), 32);
  for (const Contact3& c : m.contacts3)
    for (const SubContact& s : c.subs)
      mix(h, &s.fn, sizeof s.fn), mix(h, &s.fs, 8), mix(h, &s.fs2, 8);
  mix(h, &m.time, sizeof m.time);
  return h;
}

double joint_size(const Model& m) {
  double s = 0.0;
  if (m.dim == 3) {
    for (const Contact3& c : m.contacts3)
      for (const SubContact& sc : c.subs) s += sc.area;
  } else {
    for (size_t i = 0; i < m.contacts.size(); ++i) s += m.contacts.length[i];
  }
  return s;
}

std::string wedge_script(double phi, double dip_a, double dd_a, double dip_b, double dd_b) {
  char buf[600];
  std::snprintf(buf, sizeof buf,
                "dimension 3\ntolerance 0.01\nmaterial define rock density=2600\n"
                "joint define j kn=1e10 ks=1e10 friction=%.12g\njoint assign j\n"
                "region -12,0,-14 12,14,0 material=rock\n"
                "crack dip=%.12g ddir=%.12g origin=0,0,-6 name=A\n"
                "crack dip=%.12g ddir=%.12g origin=0,0,-6 name=B\n"
                "group wedge at=0,0.5,-0.5\nfix all\nfree group=wedge\ngravity 0 0 -9.81\n",
                phi, dip_a, dd_a, dip_b, dd_b);
  return buf;
}

double wedge_limit_angle(const Eigen::Vector3d& na, const Eigen::Vector3d& nb) {
  Eigen::Vector3d s = na.cross(nb).normalized();
  if (s.z() > 0) s = -s;
  Eigen::Matrix3d a;
  a.col(0) = na, a.col(1) = nb, a.col(2) = -s;
  const Eigen::Vector3d x = a.colPivHouseholderQr().solve(Eigen::Vector3d(0, 0, 1));  // unit weight
  return std::atan(x(2) / (x(0) + x(1))) * 180.0 / M_PI;
}

double fitted_slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < x.size(); ++i)
    sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

int run_tests(QObject& test, int argc, char** argv) {
  std::vector<char*> args;
  QStringList skip;
  for (int i = 0; i < argc; ++i) {
    if (std::strcmp(argv[i], "--skip") == 0 && i + 1 < argc) {
      skip = QString(argv[++i]).split(',');
      continue;
    }
    args.push_back(argv[i]);
  }
  // The test functions not skipped, named on the command line as Qt Test takes them.
  std::vector<QByteArray> names;
  if (!skip.isEmpty()) {
    const QMetaObject* meta = test.metaObject();
    for (int k = meta->methodOffset(); k < meta->methodCount(); ++k) {
      const QMetaMethod f = meta->method(k);
      const QByteArray name = f.name();
      if (f.methodType() != QMetaMethod::Slot || f.access() != QMetaMethod::Private ||
          f.parameterCount() != 0 || name.endsWith("_data") || name == "initTestCase" ||
          name == "cleanupTestCase" || name == "init" || name == "cleanup" ||
          skip.contains(QString::fromLatin1(name)))
        continue;
      names.push_back(name);
    }
    if (names.empty()) return 0;  // every function runs in a shard of its own
  }
  for (QByteArray& n : names) args.push_back(n.data());
  return QTest::qExec(&test, static_cast<int>(args.size()), args.data());
}

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace tessera::test
