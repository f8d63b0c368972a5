// Interpreter core: reading lines, splitting words, evaluating numbers, selecting blocks.
#include "tessera/script/script.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "tessera/core/history.hpp"
#include "tessera/generation/cutting.hpp"
#include "tessera/script/expr.hpp"
#include "tessera/support/anchor3.hpp"

namespace fs = std::filesystem;

namespace tessera {

namespace {

// Removes a comment (';' or '#' outside quotes) from a line.
std::string strip_comment(const std::string& line) {
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '"') quoted = !quoted;
    if (!quoted && (line[i] == ';' || line[i] == '#')) return line.substr(0, i);
  }
  return line;
}

// Splits at white space, keeping quoted text and parenthesised groups whole.
std::vector<std::string> split_words(const std::string& line) {
  std::vector<std::string> words;
  std::string cur;
  int depth = 0;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    if (!quoted && c == '(') ++depth;
    if (!quoted && c == ')') --depth;
    if (!quoted && depth <= 0 && std::isspace(static_cast<unsigned char>(c))) {
      if (!cur.empty()) words.push_back(cur), cur.clear();
      continue;
    }
    cur += c;
  }
  if (!cur.empty()) words.push_back(cur);
  return words;
}

// Edit distance with transpositions (optimal string alignment), for "did you mean" hints.
size_t distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] =
          std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

}  // namespace

std::string suggest(const std::string& word, const std::vector<std::string>& options) {
  std::string best;
  size_t best_d = 3;
  for (const auto& o : options) {
    const size_t d = distance(word, o);
    if (d < best_d) best_d = d, best = o;
  }
  return best.empty() ? std::string() : " (did you mean '" + best + "'?)";
}

Interpreter::Interpreter(std::string out_dir, Log log)
    : out_dir_(std::move(out_dir)), log_(std::move(log)) {
  if (!log_) log_ = [](const std::string& s) { std::cout << s << std::endl; };
}

void Interpreter::log(const std::string& s) const {
  log_(s);
}

void Interpreter::warn(const std::string& message) {
  const std::string line = file_ + ":" + std::to_string(line_) + ": warning: " + message;
  summary_.warnings.push_back(line);
  log(line);
}

void Interpreter::fail(const std::string& message) const {
  throw ScriptError(file_, line_, message);
}

void Interpreter::run_file(const std::string& path) {
  const std::string saved_file = file_;
  const int saved_line = line_;
  // A folder opens as a stream on Linux and reads as empty: refuse it by name.
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    if (call_depth_ > 0) fail("'" + path + "' is a folder, not a script file");
    throw ScriptError(path, 0, "is a folder, not a script file");
  }
  std::ifstream in(path);
  if (!in) {
    if (call_depth_ > 0) fail("cannot open '" + path + "'");
    throw ScriptError(path, 0, "cannot open the script file");
  }
  if (call_depth_ >= 32) fail("'call' nests more than 32 files deep (a file calls itself?)");
  const std::string dir = fs::path(path).parent_path().string();
  dir_stack_.push_back(dir.empty() ? std::string(".") : dir);
  ++call_depth_;
  // Leave the interpreter as it was on the way out, error or not (the GUI goes on using it).
  struct Restore {
    Interpreter& self;
    ~Restore() { self.dir_stack_.pop_back(), --self.call_depth_; }
  } restore{*this};
  std::string text;
  int n = 0;
  while (std::getline(in, text)) {
    ++n;
    // A UTF-8 byte-order mark (some Windows editors write one) is not part of the first word.
    if (n == 1 && text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
    // A stop from another thread ends the script between lines as well as inside a run.
    if (stop_ && stop_->load()) {
      log("stopped before " + path + ":" + std::to_string(n));
      break;
    }
    execute(text, path, n);
  }
  file_ = saved_file, line_ = saved_line;
}

void Interpreter::execute(const std::string& text, const std::string& file, int line) {
  file_ = file, line_ = line;
  const std::vector<std::string> words = split_words(strip_comment(text));
  if (words.empty()) return;
  Args a;
  a.command = words[0];
  std::transform(a.command.begin(), a.command.end(), a.command.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (size_t i = 1; i < words.size(); ++i) {
    const std::string& w = words[i];
    const size_t eq = w.find('=');
    if (a.command != "set" && eq != std::string::npos && eq > 0 && w[0] != '"' && w[0] != '(')
      a.keys.emplace_back(w.substr(0, eq), w.substr(eq + 1));
    else
      a.words.push_back(w);
  }
  a.used.assign(a.keys.size(), false);
  const auto& h = model_.dim == 3 ? handlers3() : handlers();
  const auto it = h.find(a.command);
  if (it == h.end()) {
    std::vector<std::string> names;
    for (const auto& [name, fn] : h) names.push_back(name);
    fail("unknown command '" + a.command + "'" + suggest(a.command, names));
  }
  text_ = text;
  // 'call' is not rolled back as a whole: its lines are, one by one.
  std::unique_ptr<Model> backup;
  if (rollback_ && a.command != "call" &&
      (rollback_runs_ || (a.command != "step" && a.command != "solve")))
    backup = std::make_unique<Model>(model_);
  try {
    try {
      if (!follow_table(a)) (this->*(it->second))(a);
    } catch (const ScriptError&) {
      throw;
    } catch (const std::exception& e) {
      fail(e.what());
    }
  } catch (const ScriptError&) {
    if (backup) {
      model_ = std::move(*backup);
      log("the model is as it was before this command");
    }
    throw;
  }
}

SavePoint Interpreter::save_point() const {
  return {model_,
          vars_,
          title_,
          stages_,
          summary_,
          limits_,
          vtk_interval_,
          overlap_checked_,
          proceed_on_errors_,
          tables_,
          timed_};
}

void Interpreter::restore(const SavePoint& p) {
  model_ = p.model, vars_ = p.vars, title_ = p.title, stages_ = p.stages, summary_ = p.summary;
  limits_ = p.limits, vtk_interval_ = p.vtk_interval, overlap_checked_ = p.overlap_checked;
  proceed_on_errors_ = p.proceed_on_errors, tables_ = p.tables, timed_ = p.timed;
}

double Interpreter::num(const std::string& text) const {
  ExprContext ctx;
  ctx.variable = [this](const std::string& name, double& v) {
    const auto it = vars_.find(name);
    if (it != vars_.end()) return v = it->second, true;
    if (name == "cycle") return v = static_cast<double>(model_.cycle), true;
    if (name == "time") return v = model_.time, true;
    if (name == "ratio") return v = model_.ratio, true;
    if (name == "timestep") return v = model_.dt, true;
    if (name == "slipping") return v = static_cast<double>(slipping_contacts(model_)), true;
    return false;
  };
  ctx.function = [this](const std::string& f, const std::vector<double>& args, double& v) {
    // blockat(x,y[,z]): the number of the block holding the point.
    if (f == "blockat") {
      if (args.size() != static_cast<size_t>(model_.dim))
        throw ExprError(model_.dim == 3 ? "write blockat(x,y,z)" : "write blockat(x,y)");
      std::ostringstream shown;
      for (size_t k = 0; k < args.size(); ++k) shown << (k ? "," : "") << args[k];
      return v = static_cast<double>(block_id(block_at(args, shown.str()))), true;
    }
    HistoryQuantity q;
    bool per_block = false;
    if (!parse_history_quantity(f, q, per_block) || !per_block || args.size() != 1) return false;
    const auto id = static_cast<int64_t>(args[0]);
    const int64_t b = block_index(id);
    if (b < 0)
      throw ExprError(f + "(" + std::to_string(id) + "): there is no block " + std::to_string(id));
    v = history_value(model_, {q, static_cast<int32_t>(b), -1, ""});
    return true;
  };
  try {
    return evaluate(text, ctx);
  } catch (const ExprError& e) {
    fail(e.what());
  }
}

Vec2 Interpreter::point(const std::string& text) const {
  const auto parts = split_top_level(text);
  if (parts.size() != 2) fail("'" + text + "' is not a point: write it as x,y");
  return {num(parts[0]), num(parts[1])};
}

int64_t Interpreter::integer(const std::string& text, int64_t min) const {
  const double v = num(text);
  if (v != std::floor(v) || v < static_cast<double>(min) || v > 9e15)
    fail("'" + text + "' must be a whole number from " + std::to_string(min) + " to 9e15");
  return static_cast<int64_t>(v);
}

bool Interpreter::take(Args& a, const std::string& key, std::string& value) const {
  for (size_t i = 0; i < a.keys.size(); ++i)
    if (a.keys[i].first == key) {
      if (a.used[i]) fail("'" + key + "' is given twice");
      a.used[i] = true;
      value = a.keys[i].second;
      return true;
    }
  return false;
}

bool Interpreter::take_num(Args& a, const std::string& key, double& value) const {
  std::string s;
  if (!take(a, key, s)) return false;
  value = num(s);
  return true;
}

namespace {
// Keywords of some command: a key given that is one of these is not a misspelling of another.
const std::vector<std::string>& common_keywords() {
  static const std::vector<std::string> words = {
      "density",  "kn",      "ks",       "friction",
      "cohesion", "tension", "dilation", "dilation_limit",
      "law",      "group",   "material", "block",
      "at",       "x",       "y",        "z",
      "vx",       "vy",      "vz",       "omega",
      "ratio",    "cycles",  "label",    "safety",
      "groups",   "origin",  "brick",    "courses",
      "bricks",   "E",       "nu",       "K",
      "G",        "model"};
  return words;
}
}  // namespace

void Interpreter::missing(const Args& a, const std::string& key, const std::string& what) const {
  const auto& known = common_keywords();
  for (size_t i = 0; i < a.keys.size(); ++i)
    if (!a.used[i] && std::find(known.begin(), known.end(), a.keys[i].first) == known.end() &&
        !suggest(a.keys[i].first, {key}).empty())
      fail(what + " needs " + key + "= ('" + a.keys[i].first + "' is not a keyword of '" +
           a.command + "'; did you mean '" + key + "'?)");
  fail(what + " needs " + key + "=");
}

void Interpreter::done(Args& a) const {
  for (size_t i = 0; i < a.keys.size(); ++i)
    if (!a.used[i]) {
      std::vector<std::string> known;
      for (size_t j = 0; j < a.keys.size(); ++j)
        if (a.used[j]) known.push_back(a.keys[j].first);
      // (A keyword of other commands, or of the other dimension, suggests nothing.)
      std::vector<std::string> others;
      for (const std::string& w : common_keywords())
        if (w != a.keys[i].first) others.push_back(w);
      fail("'" + a.keys[i].first + "' is not a keyword of '" + a.command + "'" +
           suggest(a.keys[i].first, others));
    }
}

// A block's number (kept when others are deleted, as messages, the window and VTK show it) and
// its index; -1 if no block has the number.
int Interpreter::block_id(size_t b) const {
  return model_.dim == 3 ? model_.blocks3.id[b] : model_.blocks.id[b];
}

int64_t Interpreter::block_index(int64_t id) const {
  const std::vector<int>& ids = model_.dim == 3 ? model_.blocks3.id : model_.blocks.id;
  const auto it = std::find(ids.begin(), ids.end(), id);
  return it == ids.end() ? -1 : static_cast<int64_t>(it - ids.begin());
}

// The block holding a point (X,Y or X,Y,Z), or else the one whose surface is nearest within
// the contact tolerance (a point on a face or edge, as on the top of a column).
size_t Interpreter::block_at(const std::string& v) const {
  if (model_.dim == 3) {
    const Vec3 p = point3(v);
    return block_at({p.x(), p.y(), p.z()}, v);
  }
  const Vec2 p = point(v);
  return block_at({p.x(), p.y()}, v);
}

size_t Interpreter::block_at(const std::vector<double>& xyz, const std::string& shown) const {
  if (model_.dim == 3) {
    const int b = block3_at(model_, Vec3(xyz[0], xyz[1], xyz[2]), model_.tolerance());
    if (b < 0)
      fail("no block contains the point " + shown + " or has its surface within the tolerance");
    return static_cast<size_t>(b);
  }
  const Blocks& B = model_.blocks;
  const Vec2 p(xyz[0], xyz[1]);
  size_t best = B.size();
  double nearest = std::max(model_.tolerance(), 0.0);
  for (size_t b = 0; b < B.size() && (best == B.size() || nearest > 0.0); ++b) {
    const std::vector<Vec2> poly = B.world_polygon(b);
    if (point_in_polygon(p, poly)) {
      best = b, nearest = 0.0;
      break;
    }
    for (size_t k = 0; k < poly.size(); ++k)
      if (const double d = segment_distance(p, poly[k], poly[(k + 1) % poly.size()]); d <= nearest)
        nearest = d, best = b;
  }
  if (best == B.size())
    fail("no block contains the point " + shown + " or has its outline within the tolerance");
  return best;
}

std::vector<size_t> Interpreter::select(Args& a, bool allow_words) {
  const Blocks& B = model_.blocks;
  std::string v;
  bool any = false;
  const Blocks3& B3 = model_.blocks3;
  const bool three = model_.dim == 3;
  double x0 = -1e300, x1 = 1e300, y0 = -1e300, y1 = 1e300, z0 = -1e300, z1 = 1e300;
  int group = -2;
  std::vector<size_t> ids;
  if (take(a, "x", v)) {
    const Vec2 r = point(v);
    x0 = std::min(r.x(), r.y()), x1 = std::max(r.x(), r.y()), any = true;
  }
  if (take(a, "y", v)) {
    const Vec2 r = point(v);
    y0 = std::min(r.x(), r.y()), y1 = std::max(r.x(), r.y()), any = true;
  }
  if (take(a, "z", v)) {
    if (!three) fail("z= selects blocks of 3D models; this model is 2D");
    const Vec2 r = point(v);
    z0 = std::min(r.x(), r.y()), z1 = std::max(r.x(), r.y()), any = true;
  }
  if (take(a, "group", v)) {
    group = model_.group_index(v, false);
    if (group < 0) fail("there is no group '" + v + "'" + suggest(v, model_.groups));
    any = true;
  }
  if (take(a, "block", v)) {
    for (const auto& part : split_top_level(v)) {
      const int64_t id = integer(part, 1);
      const int64_t b = block_index(id);
      if (b < 0)
        fail("there is no block " + std::to_string(id) + " (the model has " +
             std::to_string(model_.block_count()) +
             " blocks; deleted blocks' numbers are not used again)");
      ids.push_back(static_cast<size_t>(b));
    }
    any = true;
  }
  if (take(a, "at", v)) {
    ids.push_back(block_at(v));
    any = true;
  }
  // Centroid inside a circle X,Y,R, or a point inside the block inside a polygon (X,Y X,Y ...).
  double cx = 0, cy = 0, cr = -1;
  if (take(a, "circle", v)) {
    if (three) fail("circle= selects blocks of 2D models; in 3D use x=, y=, z= ranges");
    const auto parts = split_top_level(v);
    if (parts.size() != 3) fail("write circle=X,Y,R");
    cx = num(parts[0]), cy = num(parts[1]), cr = num(parts[2]);
    any = true;
  }
  std::vector<Vec2> inside;
  if (take(a, "polygon", v)) {
    if (three) fail("polygon= selects blocks of 2D models; in 3D use x=, y=, z= ranges");
    std::string body = v;
    if (body.size() >= 2 && body.front() == '(' && body.back() == ')')
      body = body.substr(1, body.size() - 2);
    std::istringstream in(body);
    for (std::string w; in >> w;) inside.push_back(point(w));
    if (inside.size() < 3) fail("write polygon=(X,Y X,Y X,Y ...) with at least three points");
    any = true;
  }
  // Blocks with an edge on a named joint set, crack or opening.
  int joints = -2;
  if (take(a, "joints", v)) {
    joints = -1;
    for (size_t t = 0; t < model_.joint_tags.size(); ++t)
      if (model_.joint_tags[t] == v) joints = static_cast<int>(t);
    if (joints < 0) fail("there are no joints named '" + v + "'" + suggest(v, model_.joint_tags));
    any = true;
  }
  // Blocks smaller than an area (to clear out the crumbs a random joint pattern leaves).
  double smaller = -1.0;
  if (take(a, "smaller", v)) smaller = num(v), any = true;
  auto& words = a.words;
  const auto it = std::find(words.begin(), words.end(), "all");
  if (it != words.end()) words.erase(it), any = true;
  if (!any)
    fail("'" + a.command + "' needs blocks to act on: all, block=ID, " +
         (three ? "at=X,Y,Z, group=NAME, x=X0,X1, y=Y0,Y1, z=Z0,Z1"
                : "at=X,Y, group=NAME, x=X0,X1, y=Y0,Y1"));
  if (!allow_words && !words.empty())
    fail("unexpected word '" + words[0] + "' after '" + a.command + "'");
  std::vector<size_t> out;
  for (size_t b = 0; b < B3.size(); ++b) {
    const Vec3& c = B3.body[b].position;
    if (!ids.empty() && std::find(ids.begin(), ids.end(), b) == ids.end()) continue;
    if (group >= -1 && B3.group[b] != group) continue;
    if (c.x() < x0 || c.x() > x1 || c.y() < y0 || c.y() > y1 || c.z() < z0 || c.z() > z1) continue;
    if (smaller >= 0.0 && B3.volume[b] >= smaller) continue;
    const auto t0 = B3.face_tag.begin() + B3.face_begin[b],
               t1 = B3.face_tag.begin() + B3.face_begin[b + 1];
    if (joints >= 0 && std::find(t0, t1, joints) == t1) continue;
    out.push_back(b);
  }
  for (size_t b = 0; b < B.size(); ++b) {
    if (!ids.empty() && std::find(ids.begin(), ids.end(), b) == ids.end()) continue;
    if (group >= -1 && B.group[b] != group) continue;
    if (B.x[b] < x0 || B.x[b] > x1 || B.y[b] < y0 || B.y[b] > y1) continue;
    if (smaller >= 0.0 && B.area[b] >= smaller) continue;
    if (cr >= 0.0 && std::hypot(B.x[b] - cx, B.y[b] - cy) > cr) continue;
    // A point inside the block, not its centroid (outside a concave block, e.g. one the
    // opening's outline bites into).
    if (!inside.empty() && !point_in_polygon(interior_point(B.world_polygon(b)), inside)) continue;
    if (joints >= 0 &&
        std::find(B.edge_tag.begin() + B.vert_begin[b], B.edge_tag.begin() + B.vert_begin[b + 1],
                  joints) == B.edge_tag.begin() + B.vert_begin[b + 1])
      continue;
    out.push_back(b);
  }
  if (out.empty()) fail("no block matches the selection of '" + a.command + "'");
  return out;
}

std::string Interpreter::resolve(const std::string& path, bool for_reading) const {
  const fs::path p(path);
  if (p.is_absolute()) return path;
  const fs::path in_out = fs::path(out_dir_) / p;
  if (!for_reading || fs::exists(in_out)) return in_out.string();
  return (fs::path(dir_stack_.back()) / p).string();
}

}  // namespace tessera
