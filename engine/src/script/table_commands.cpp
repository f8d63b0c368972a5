// Tables (time histories) and the commands that follow them: `table NAME FILE.csv`,
// `table NAME T,V T,V ...`, `table stop`, and table=NAME on velocity, boundary and gravity.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "tessera/script/expr.hpp"
#include "tessera/script/script.hpp"

namespace tessera {

double Table::at(double t) const {
  if (t <= time.front()) return value.front();
  if (t >= time.back()) return value.back();
  const size_t k =
      static_cast<size_t>(std::upper_bound(time.begin(), time.end(), t) - time.begin());
  const double w = (t - time[k - 1]) / (time[k] - time[k - 1]);
  return value[k - 1] + w * (value[k] - value[k - 1]);
}

void Interpreter::set_table(const std::string& name, Table t) {
  const bool word = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
  if (!word || name == "stop")
    throw std::invalid_argument("a table's name is a word of letters, digits and _ (not 'stop')");
  if (t.time.empty() || t.time.size() != t.value.size())
    throw std::invalid_argument("table '" + name + "' needs as many values as times, at least one");
  for (size_t i = 0; i < t.time.size(); ++i) {
    if (!std::isfinite(t.time[i]) || !std::isfinite(t.value[i]))
      throw std::invalid_argument("table '" + name + "': point " + std::to_string(i + 1) +
                                  " is not a finite number");
    if (i > 0 && !(t.time[i] > t.time[i - 1]))
      throw std::invalid_argument("table '" + name + "': the times must increase (point " +
                                  std::to_string(i + 1) + ")");
  }
  tables_[name] = std::move(t);
}

namespace {
// The fields of a CSV line: separated by commas, semicolons or white space.
std::vector<std::string> fields(const std::string& line) {
  std::string s = line;
  std::replace_if(
      s.begin(), s.end(), [](char c) { return c == ',' || c == ';'; }, ' ');
  std::istringstream in(s);
  std::vector<std::string> out;
  for (std::string f; in >> f;) out.push_back(f);
  return out;
}
bool parse(const std::string& text, double& v) {
  char* end = nullptr;
  v = std::strtod(text.c_str(), &end);
  return end && *end == '\0' && end != text.c_str();
}
}  // namespace

void Interpreter::cmd_table(Args& a) {
  if (a.words.size() == 1 && a.words[0] == "stop") {
    done(a);
    log("table stop: " + std::to_string(timed_.size()) + " commands no longer follow tables");
    timed_.clear();
    return;
  }
  if (a.words.size() < 2)
    fail("write 'table NAME FILE.csv', 'table NAME T,V T,V ...' or 'table stop'");
  done(a);
  const std::string name = a.words[0];
  Table t;
  if (a.words.size() == 2 && a.words[1].find(',') == std::string::npos) {
    // A file of time,value lines; a first line that is not numbers is a heading.
    const std::string path = resolve(a.words[1], true);
    std::ifstream in(path);
    if (!in) fail("cannot open '" + a.words[1] + "'");
    std::string line;
    bool first = true;
    for (int n = 1; std::getline(in, line); ++n) {
      if (const size_t hash = line.find('#'); hash != std::string::npos) line.erase(hash);
      const auto f = fields(line);
      if (f.empty()) continue;
      double tv = 0, vv = 0;
      const bool numbers = f.size() >= 2 && parse(f[0], tv) && parse(f[1], vv);
      if (!numbers && first && !parse(f[0], tv)) {
        first = false;
        continue;
      }
      first = false;
      if (!numbers) fail(a.words[1] + ":" + std::to_string(n) + ": write time,value (two numbers)");
      t.time.push_back(tv), t.value.push_back(vv);
    }
  } else {
    for (size_t i = 1; i < a.words.size(); ++i) {
      const auto pair = split_top_level(a.words[i]);
      if (pair.size() != 2) fail("'" + a.words[i] + "' is not a pair T,V");
      t.time.push_back(num(pair[0])), t.value.push_back(num(pair[1]));
    }
  }
  try {
    set_table(name, t);
  } catch (const std::invalid_argument& e) {
    fail(e.what());
  }
  char buf[160];
  std::snprintf(buf, sizeof buf, "table %s: %zu points from %g to %g s", name.c_str(),
                t.time.size(), t.time.front(), t.time.back());
  log(buf);
}

bool Interpreter::follow_table(const Args& a) {
  const auto it = std::find_if(a.keys.begin(), a.keys.end(),
                               [](const auto& kv) { return kv.first == "table"; });
  if (it == a.keys.end()) return false;
  const std::string& c = a.command;
  if (c != "velocity" && c != "boundary" && c != "gravity" && c != "load")
    fail("table= goes with 'velocity', 'load', 'boundary velocity|stress|pressure' and 'gravity'");
  const auto has = [&](const char* key) {
    return std::any_of(a.keys.begin(), a.keys.end(),
                       [&](const auto& kv) { return kv.first == key; });
  };
  const bool velocity = has("velocity") || has("vx") || has("vy") || has("vz");
  if (c == "boundary" && !velocity && !has("stress") && !has("pressure"))
    fail("table= goes with boundary velocity= (or vx= vy= vz=), stress= or pressure=");
  if (!tables_.count(it->second)) {
    std::vector<std::string> names;
    for (const auto& [n, t] : tables_) names.push_back(n);
    fail("there is no table '" + it->second + "'" + suggest(it->second, names));
  }
  TimedCommand t;
  t.args = a;
  t.args.keys.erase(t.args.keys.begin() + (it - a.keys.begin()));
  t.args.used.assign(t.args.keys.size(), false);
  t.table = it->second, t.file = file_, t.line = line_;
  // Stress and pressure add loads each time they run; the rest set a value.
  t.incremental = c == "boundary" && !velocity;
  t.applied = tables_.at(t.table).at(model_.time);
  run_scaled(t, t.applied);
  timed_.push_back(std::move(t));
  return true;
}

void Interpreter::run_scaled(const TimedCommand& t, double scale) {
  char factor[40];
  std::snprintf(factor, sizeof factor, ")*(%.17g)", scale);
  const auto scaled = [&](const std::string& text) {
    std::string out;
    for (const std::string& part : split_top_level(text))
      out.append(out.empty() ? "(" : ",(").append(part).append(factor);
    return out;
  };
  Args a = t.args;
  for (auto& [key, value] : a.keys)
    if (key == "vx" || key == "vy" || key == "vz" || key == "omega" || key == "wx" || key == "wy" ||
        key == "wz" || key == "velocity" || key == "stress" || key == "pressure" || key == "fx" ||
        key == "fy" || key == "fz" || key == "mx" || key == "my" || key == "mz" || key == "moment")
      value = scaled(value);
  if (a.command == "gravity")
    for (std::string& w : a.words) w = scaled(w);
  const auto& h = model_.dim == 3 ? handlers3() : handlers();
  (this->*(h.at(a.command)))(a);
}

void Interpreter::apply_tables() {
  if (timed_.empty()) return;
  // Quietly, and at the line that asked for it (an error names it).
  struct Restore {
    Interpreter& self;
    std::string file;
    int line;
    Log log;
    ~Restore() { self.file_ = file, self.line_ = line, self.log_ = std::move(log); }
  } restore{*this, file_, line_, std::move(log_)};
  log_ = [](const std::string&) {};
  for (TimedCommand& t : timed_) {
    const double s = tables_.at(t.table).at(model_.time);
    if (s == t.applied) continue;
    file_ = t.file, line_ = t.line;
    run_scaled(t, t.incremental ? s - t.applied : s);
    t.applied = s;
  }
}

}  // namespace tessera
