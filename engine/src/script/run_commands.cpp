// Script commands that run the model and write results: step, solve, histories, output, state.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "tessera/core/parallel.hpp"
#include "tessera/core/strength_reduction.hpp"
#include "tessera/io/state_io.hpp"
#include "tessera/script/expr.hpp"
#include "tessera/script/script.hpp"
#include "tessera/zones/deformable.hpp"

namespace fs = std::filesystem;

namespace tessera {

namespace {
std::string progress_line(const Model& m, double elapsed) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "cycle %10llu  ratio %9.3e  time %11.5e s  elapsed %7.1f s",
                static_cast<unsigned long long>(m.cycle), m.ratio, m.time, elapsed);
  return buf;
}
}  // namespace

// How far the model's farthest block centroid lies from the origin along an axis (m).
static double farthest_coordinate(const Model& m) {
  double far = 0.0;
  for (size_t b = 0; b < m.blocks.size(); ++b)
    far = std::max({far, std::abs(m.blocks.x[b]), std::abs(m.blocks.y[b])});
  for (const RigidBody3& body : m.blocks3.body)
    far = std::max(far, body.position.cwiseAbs().maxCoeff());
  return far;
}

void Interpreter::check_ready() {
  if (!overlap_checked_) {
    for (size_t b = 0; b < model_.blocks.size(); ++b) model_.blocks.update_world(b);
    run_checks(true);
    overlap_checked_ = true;
  }
  // Coordinates far from the origin round to more than the gaps the joints tell from shut (ten
  // times the model's round-off gap): said once.
  if (far_warned_) return;
  const double far = farthest_coordinate(model_);
  const double quantum = far * std::numeric_limits<double>::epsilon();
  if (quantum > 10.0 * model_.roundoff_gap()) {
    far_warned_ = true;
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "the model lies %.3g m from the origin, where coordinates round to %.2g m, more "
                  "than the joints' gaps can bear: it may not settle (ratio stalling, blocks "
                  "creeping); give the coordinates from a local origin near the model",
                  far, quantum);
    warn(buf);
  }
}

void Interpreter::run_with_progress(const std::function<bool(const Progress&)>& body,
                                    const std::string& what) {
  check_ready();
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  auto last = t0;
  const uint64_t c0 = model_.cycle, lost0 = model_.lost_dilated;
  const Progress progress = [&](const Model& m) {
    if (vtk_interval_ && m.cycle % vtk_interval_ == 0) {
      if (!vtk_) vtk_ = std::make_unique<VtkSeries>((fs::path(out_dir_) / "vtk").string());
      vtk_->write(m);
    }
    // Loads that follow tables (not in the trials of `solve fos`, which run on copies).
    if (&m == &model_) apply_tables();
    if (observer_) observer_(m);
    if (m.cycle % 64 == 0) {
      const auto now = Clock::now();
      if (progress_seconds_ > 0 &&
          std::chrono::duration<double>(now - last).count() >= progress_seconds_) {
        last = now;
        log(progress_line(m, std::chrono::duration<double>(now - t0).count()));
      }
      if (stop_ && stop_->load()) return false;
    }
    return true;
  };
  try {
    body(progress);
  } catch (const ModelError& e) {
    summary_.cycles_run += model_.cycle - c0;
    fail(e.what());
  }
  const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
  summary_.cycles_run += model_.cycle - c0;
  stages_.push_back({text_, file_, line_, c0, model_.cycle, false});
  summary_.wall_seconds += wall;
  log(what + ": " + progress_line(model_, wall));
  if (model_.lost_dilated > lost0) {
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "%llu contacts held shut by joint dilation (up to %.3g m) opened beyond the "
                  "contact tolerance (%.3g m) and were lost with their forces: raise it with "
                  "'tolerance' above the dilation expected",
                  static_cast<unsigned long long>(model_.lost_dilated - lost0),
                  model_.lost_dilation, model_.tolerance());
    warn(buf);
  }
}

void Interpreter::warn_history_size(uint64_t cycles) {
  const Histories& h = model_.histories;
  if (h.series.empty() || h.interval == 0) return;
  // About 17 characters a value in the CSV, and 8 bytes a value in memory.
  const double rows = double(h.rows()) + double(cycles) / double(h.interval);
  const double mb = rows * (12.0 + 17.0 * double(h.columns())) / 1e6;
  if (mb < 100.0) return;
  char buf[300];
  std::snprintf(buf, sizeof buf,
                "the histories will reach %.3g rows: about %.0f MB in history.csv and %.0f MB of "
                "memory; thin them with 'history interval %.0f' (100,000 rows) before this line",
                rows, mb, rows * 8.0 * double(h.columns() + 1) / 1e6,
                std::ceil(double(h.interval) * rows / 1e5));
  warn(buf);
}

void Interpreter::cmd_step(Args& a) {
  if (a.words.size() != 1) fail("write 'step N' with the number of cycles N");
  const auto n = static_cast<uint64_t>(integer(a.words[0], 0));
  done(a);
  warn_history_size(n);
  run_with_progress([&](const Progress& p) { return run_cycles(model_, n, p, 1) == n; }, "step");
}

void Interpreter::cmd_solve(Args& a) {
  if (!a.words.empty() && a.words[0] == "fos") return solve_fos(a);
  if (!a.words.empty())
    fail("unexpected word '" + a.words[0] + "' (write 'solve ratio=R cycles=N')");
  double ratio = 1e-5, cycles = 1e6;
  take_num(a, "ratio", ratio);
  take_num(a, "cycles", cycles);
  done(a);
  if (ratio <= 0.0) fail("the ratio limit must be positive");
  if (cycles < 1 || cycles != std::floor(cycles))
    fail("the cycle limit must be a whole number of at least 1");
  warn_history_size(static_cast<uint64_t>(cycles));
  SolveResult r;
  run_with_progress(
      [&](const Progress& p) {
        r = solve(model_, ratio, static_cast<uint64_t>(cycles), p, 1);
        return r.converged;
      },
      "solve");
  stages_.back().converged = r.converged;
  if (!r.converged && !r.stopped) {
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "solve stopped at the cycle limit (%.0f) with ratio %.3e above %.3e", cycles,
                  model_.ratio, ratio);
    warn(buf);
  }
}

void Interpreter::solve_fos(Args& a) {
  if (a.words.size() > 1) fail("unexpected word '" + a.words[1] + "'");
  FosOptions o;
  const auto on_off = [&](const char* key, bool& value) {
    std::string v;
    if (!take(a, key, v)) return;
    if (v != "on" && v != "off") fail(std::string("write ") + key + "=on or " + key + "=off");
    value = v == "on";
  };
  on_off("joints", o.joints);
  on_off("zones", o.zones);
  double cycles = 20000;
  std::string groups;
  if (take(a, "exclude", groups))
    for (const std::string& g : split_top_level(groups)) {
      const int k = model_.group_index(g, false);
      if (k < 0) fail("there is no group '" + g + "'" + suggest(g, model_.groups));
      o.exclude.push_back(k);
    }
  take_num(a, "ratio", o.ratio);
  take_num(a, "cycles", cycles);
  done(a);
  if (o.ratio <= 0.0) fail("the ratio limit must be positive");
  if (cycles < 2 || cycles != std::floor(cycles))
    fail("the cycle limit of a trial must be a whole number of at least 2");
  if (!o.joints && !o.zones) fail("joints=off and zones=off leave no strength to reduce");
  o.cycles = static_cast<uint64_t>(cycles);
  FosResult res;
  char buf[240];
  // The trials run on copies of the model: none of their cycles joins the VTK series.
  const uint64_t vtk_interval = vtk_interval_;
  vtk_interval_ = 0;
  struct Restore {
    uint64_t& slot;
    uint64_t value;
    ~Restore() { slot = value; }
  } restore{vtk_interval_, vtk_interval};
  run_with_progress(
      [&](const Progress& p) {
        res = factor_of_safety(model_, o, p, [&](const FosTrial& t) {
          if (t.stands)
            std::snprintf(buf, sizeof buf, "fos trial %.4g: stands (%llu cycles, ratio %.2e)",
                          t.factor, static_cast<unsigned long long>(t.cycles), t.ratio);
          else if (!t.stopped.empty())
            std::snprintf(buf, sizeof buf, "fos trial %.4g: fails (%s)", t.factor,
                          t.stopped.c_str());
          else
            std::snprintf(buf, sizeof buf,
                          "fos trial %.4g: fails (%llu cycles, ratio %.2e; moved %.3g m at half "
                          "way, %.3g m at the end)",
                          t.factor, static_cast<unsigned long long>(t.cycles), t.ratio,
                          t.moved_half, t.moved_end);
          log(buf);
        });
        return res.bracketed;
      },
      "solve fos");
  if (!res.bracketed && !res.trials.empty() && res.trials.back().stopped == "stopped") {
    warn("solve fos was stopped before the factor of safety was bracketed");
    return;
  }
  summary_.fos = res.factor;
  if (!res.bracketed) {
    std::snprintf(buf, sizeof buf, "the model %s at every factor tried: factor of safety %s %g",
                  res.factor > 1.0 ? "stood" : "failed", res.factor > 1.0 ? "above" : "below",
                  res.factor);
    warn(buf);
    // Failing at every factor, even the strongest, most often means it was failing already.
    if (res.factor < 1.0 && model_.cycle > 0 && model_.ratio > o.ratio) {
      std::snprintf(buf, sizeof buf,
                    "the model was not in equilibrium before the search (ratio %.2e above "
                    "%.2e): solve it first, with 'solve ratio=%.2g'",
                    model_.ratio, o.ratio, o.ratio);
      warn(buf);
    }
  }
  std::snprintf(buf, sizeof buf, "factor of safety %.2f (%zu trials)", res.factor,
                res.trials.size());
  log(buf);
  if (!res.mechanism) return;
  // The mechanism at the smallest failing factor: a VTK snapshot, and a figure when drawn.
  fs::create_directories(out_dir_);
  VtkSeries((fs::path(out_dir_) / "fos_mechanism").string()).write(*res.mechanism);
  if (figure_sink_) {
    FigureRequest r;
    r.path = (fs::path(out_dir_) / "fos_mechanism.png").string();
    r.view.colour = ColourBy::kDisplacement;
    r.view.vectors = true;
    std::snprintf(buf, sizeof buf, "Mechanism at the smallest failing factor, %.3g", [&] {
      double f = 1e300;
      for (const FosTrial& t : res.trials)
        if (!t.stands) f = std::min(f, t.factor);
      return f;
    }());
    r.view.title = buf;
    figure_sink_(r, *res.mechanism);
    log("figure " + r.path);
  }
}

namespace {
// The solid zone whose centroid is nearest p, or -1 if there is none.
template <int D>
int32_t nearest_zone(const ContinuumT<D>& c, const typename ContinuumT<D>::Vec& p) {
  int32_t best = -1;
  double d = 1e300;
  for (size_t z = 0; z < c.zone_count(); ++z) {
    if (c.material[z] == 0) continue;
    typename ContinuumT<D>::Vec centre = ContinuumT<D>::Vec::Zero();
    for (uint32_t n : c.zones[z]) centre += c.pos[n];
    if (const double e = (centre / (D + 1.0) - p).norm(); e < d)
      d = e, best = static_cast<int32_t>(z);
  }
  return best;
}
}  // namespace

void Interpreter::cmd_history(Args& a) {
  if (a.words.size() == 2 && a.words[0] == "interval") {
    model_.histories.interval = static_cast<uint32_t>(integer(a.words[1], 1));
    done(a);
    return;
  }
  if (a.words.size() != 1)
    fail("write 'history QUANTITY [block=ID | at=X,Y] [label=NAME]' or 'history interval N'");
  // (zone quantities sxx ... sigma3 take at= too: the zone nearest the point)
  HistorySeries s;
  bool per_block = false;
  if (!parse_history_quantity(a.words[0], s.quantity, per_block))
    fail("'" + a.words[0] + "' is not a history quantity" +
         suggest(a.words[0], history_quantity_names()));
  s.label = a.words[0];
  if (per_block) {
    a.words.clear();
    std::string label;
    const bool has_label = take(a, "label", label);
    // For a deformable block, its node nearest the point (or the centroid).
    Vec2 where(std::nan(""), std::nan(""));
    Vec3 where3 = Vec3::Constant(std::nan(""));
    for (const auto& kv : a.keys) {
      if (kv.first != "at") continue;
      if (model_.dim == 2)
        where = point(kv.second);
      else
        where3 = point3(kv.second);
    }
    const auto sel = select(a);
    if (sel.size() != 1) fail("a block history needs exactly one block (block=ID or at=X,Y)");
    s.block = static_cast<int32_t>(sel[0]);
    if (model_.dim == 2 && model_.blocks.deformable[sel[0]]) {
      if (std::isnan(where.x())) where = {model_.blocks.x[sel[0]], model_.blocks.y[sel[0]]};
      const Continuum& c = model_.continuum;
      const std::vector<int> owner = node_owners(model_);
      double best = 1e300;
      for (size_t n = 0; n < c.node_count(); ++n)
        if (const double d = (c.pos[n] - where).norm();
            d < best && owner[n] == static_cast<int>(sel[0]))
          best = d, s.node = static_cast<int32_t>(n);
    }
    if (model_.dim == 3 && model_.blocks3.deformable[sel[0]]) {
      const Blocks3& B = model_.blocks3;
      if (std::isnan(where3.x())) where3 = B.body[sel[0]].position;
      const Continuum3& c = model_.continuum3;
      double best = 1e300;
      for (uint32_t n = B.node_begin[sel[0]]; n < B.node_end[sel[0]]; ++n)
        if (const double d = (c.pos[n] - where3).norm(); d < best)
          best = d, s.node = static_cast<int32_t>(n);
    }
    s.label = has_label         ? label
              : a.words.empty() ? s.label + "_" + std::to_string(sel[0] + 1)
                                : s.label;
  } else if (is_contact_quantity(s.quantity)) {
    // The force between two blocks: contact=A,B (block numbers).
    std::string pair;
    if (!take(a, "contact", pair))
      fail("a history of " + s.label + " needs contact=A,B (the numbers of the two blocks)");
    const auto ids = split_top_level(pair);
    if (ids.size() != 2) fail("write contact=A,B with the numbers of the two blocks");
    int64_t index[2];
    for (int k = 0; k < 2; ++k) {
      const int64_t id = integer(ids[static_cast<size_t>(k)], 1);
      index[k] = block_index(id);
      if (index[k] < 0) fail("there is no block " + std::to_string(id));
    }
    if (index[0] == index[1]) fail("contact=A,B needs two different blocks");
    s.block = static_cast<int32_t>(index[0]), s.element = static_cast<int32_t>(index[1]);
    s.label += "_" + ids[0] + "_" + ids[1];
    take(a, "label", s.label);
    a.words.clear();
  } else if (is_zone_quantity(s.quantity)) {
    // A zone's stress: the zone whose centre is nearest the point.
    std::string at;
    if (!take(a, "at", at))
      fail("a zone history needs at=" + std::string(model_.dim == 3 ? "X,Y,Z" : "X,Y") +
           " (the zone nearest the point)");
    take(a, "label", s.label);
    a.words.clear();
    s.zone = model_.dim == 3 ? nearest_zone(model_.continuum3, point3(at))
                             : nearest_zone(model_.continuum, point(at));
    if (s.zone < 0) fail("there are no zones: 'zone generate' makes blocks deformable");
  } else if (is_bolt_quantity(s.quantity) || is_cable_quantity(s.quantity) ||
             is_liner_quantity(s.quantity)) {
    std::string name;
    s.element = support_point(a, s.quantity, name);
    s.label += "_" + name;
    take(a, "label", s.label);
    a.words.clear();
  } else {
    take(a, "label", s.label);
  }
  done(a);
  Histories& h = model_.histories;
  if (h.find(s.label) >= 0)
    fail("a history labelled '" + s.label + "' exists already: give label=");
  // Earlier samples get no value in the new column.
  std::vector<double> values;
  values.reserve(h.rows() * (h.columns() + 1));
  for (size_t r = 0; r < h.rows(); ++r) {
    for (size_t c = 0; c < h.columns(); ++c) values.push_back(h.at(r, c));
    values.push_back(std::nan(""));
  }
  h.values = std::move(values);
  h.series.push_back(s);
}

void Interpreter::cmd_vtk(Args& a) {
  if (a.words.size() == 2 && a.words[0] == "interval") {
    vtk_interval_ = static_cast<uint64_t>(integer(a.words[1], 0));
    done(a);
    return;
  }
  if (!a.words.empty()) fail("write 'vtk' for a snapshot now or 'vtk interval N'");
  done(a);
  if (!vtk_) vtk_ = std::make_unique<VtkSeries>((fs::path(out_dir_) / "vtk").string());
  for (size_t b = 0; b < model_.blocks.size(); ++b) model_.blocks.update_world(b);
  vtk_->write(model_);
}

void Interpreter::cmd_figure(Args& a) {
  if (a.words.size() != 1)
    fail(
        "write 'figure FILE.png|.svg|.pdf [size=W,H] [colour=C] [contacts=S] [support=force] "
        "[vectors=on] "
        "[magnify=F] [window=X0,Y0,X1,Y1] [view=AZ,EL] [perspective=on] [cut=DIP,DIPDIR,X,Y,Z] "
        "[title=\"...\"]'");
  FigureRequest r;
  const std::string ext = fs::path(a.words[0]).extension().string();
  if (ext != ".png" && ext != ".svg" && ext != ".pdf")
    fail("'" + a.words[0] + "': a figure is written as .png, .svg or .pdf");
  r.view.title = title_;
  std::string v;
  if (take(a, "size", v)) {
    const Vec2 s = point(v);
    if (!(s.x() >= 16 && s.y() >= 16 && s.x() <= 16384 && s.y() <= 16384))
      fail("the figure size must be between 16 and 16384 in each direction");
    r.width = static_cast<int>(s.x()), r.height = static_cast<int>(s.y());
  }
  if (take(a, "colour", v) && !parse_colour_by(v, r.view.colour))
    fail("'" + v + "' is not something blocks are coloured by" + suggest(v, colour_by_names()));
  if (take(a, "contacts", v) && !parse_contact_show(v, r.view.contacts))
    fail("'" + v + "' is not a way of showing contacts" + suggest(v, contact_show_names()));
  if (take(a, "support", v)) {
    if (v != "state" && v != "force") fail("write support=state or support=force");
    r.view.support_force = v == "force";
  }
  if (take(a, "vectors", v)) {
    if (v != "on" && v != "off") fail("write vectors=on or vectors=off");
    r.view.vectors = v == "on";
  }
  if (take_num(a, "magnify", r.view.magnify) && !(r.view.magnify >= 0.0))
    fail("the magnification must be zero or more");
  if (take(a, "window", v)) {
    const auto parts = split_top_level(v);
    if (parts.size() != 4) fail("write window=X0,Y0,X1,Y1");
    r.view.lo = {num(parts[0]), num(parts[1])}, r.view.hi = {num(parts[2]), num(parts[3])};
    if (!(r.view.hi.x() > r.view.lo.x() && r.view.hi.y() > r.view.lo.y()))
      fail("the window's second corner must be above and right of the first");
    r.view.has_window = true;
  }
  if (take(a, "view", v)) {
    if (model_.dim != 3) fail("view= sets the viewpoint of 3D models; this model is 2D");
    const Vec2 ae = point(v);
    if (!(ae.y() >= -90.0 && ae.y() <= 90.0))
      fail("write view=AZIMUTH,ELEVATION with the elevation in [-90, 90] degrees");
    r.view.azimuth = ae.x(), r.view.elevation = ae.y();
  }
  if (take(a, "cut", v)) {
    if (model_.dim != 3) fail("cut= cuts 3D models open; this model is 2D");
    const auto parts = split_top_level(v);
    if (parts.size() != 5)
      fail(
          "write cut=DIP,DIPDIR,X,Y,Z (the plane's dip and dip direction in degrees, and a point "
          "on it)");
    r.view.cut = true;
    r.view.cut_dip = num(parts[0]), r.view.cut_dip_direction = num(parts[1]);
    r.view.cut_point = {num(parts[2]), num(parts[3]), num(parts[4])};
    if (!(r.view.cut_dip >= 0.0 && r.view.cut_dip <= 90.0))
      fail("the cut's dip must be between 0 and 90 degrees");
  }
  if (take(a, "perspective", v))
    if (const std::string e = set_perspective(r.view, v, model_.dim); !e.empty()) fail(e);
  if (take(a, "title", v)) {
    if (v.size() > 1 && v.front() == '"' && v.back() == '"') v = v.substr(1, v.size() - 2);
    r.view.title = v;
  }
  done(a);
  if (!figure_sink_) fail("figures are drawn by the tessera program; this run has no renderer");
  fs::create_directories(out_dir_);
  r.path = resolve(a.words[0], false);
  if (!fs::path(r.path).parent_path().empty())
    fs::create_directories(fs::path(r.path).parent_path());
  for (size_t b = 0; b < model_.blocks.size(); ++b) model_.blocks.update_world(b);
  figure_sink_(r, model_);
  log("figure " + r.path);
}

void Interpreter::cmd_save(Args& a) {
  if (a.words.size() != 1) fail("write 'save FILE'");
  done(a);
  fs::create_directories(out_dir_);
  save_state(model_, resolve(a.words[0], false));
}

void Interpreter::cmd_restore(Args& a) {
  if (a.words.size() != 1) fail("write 'restore FILE'");
  done(a);
  const std::string path = resolve(a.words[0], true);
  try {
    model_ = restore_state(path);
  } catch (const std::exception& e) {
    fail(e.what());
  }
  overlap_checked_ = true;
}

void Interpreter::cmd_call(Args& a) {
  if (a.words.size() != 1) fail("write 'call FILE'");
  done(a);
  const fs::path p(a.words[0]);
  run_file(p.is_absolute() ? p.string() : (fs::path(dir_stack_.back()) / p).string());
}

void Interpreter::finish() {
  fs::create_directories(out_dir_);
  const std::string csv = (fs::path(out_dir_) / "history.csv").string();
  std::ofstream out(csv);
  if (!out) throw std::runtime_error(csv + ": cannot open for writing");
  write_histories_csv(model_.histories, out);
  if (!vtk_) vtk_ = std::make_unique<VtkSeries>((fs::path(out_dir_) / "vtk").string());
  for (size_t b = 0; b < model_.blocks.size(); ++b) model_.blocks.update_world(b);
  vtk_->write(model_);
  nlohmann::json j;
  j["title"] = title_;
  j["cycles"] = model_.cycle;
  j["cycles_this_run"] = summary_.cycles_run;
  j["simulated_time"] = model_.time;
  j["timestep"] = model_.dt;
  j["wall_seconds"] = summary_.wall_seconds;
  j["final_ratio"] = model_.ratio;
  j["dimension"] = model_.dim;
  j["blocks"] = model_.block_count();
  j["contacts"] = model_.dim == 3 ? model_.contacts3.size() : model_.contacts.size();
  j["threads"] = thread_count();
  j["warnings"] = summary_.warnings;
  j["status"] = summary_.status;
  if (!summary_.error.empty()) j["error"] = summary_.error;
  if (summary_.fos) j["fos"] = *summary_.fos;
  // Bytes that are not UTF-8 (a title typed in another encoding) become U+FFFD rather than
  // stopping the write; the file is written whole and then moved in place, never left empty.
  const fs::path path = fs::path(out_dir_) / "summary.json", part = path.string() + ".part";
  {
    std::ofstream s(part);
    s << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
    if (!s) throw std::runtime_error(part.string() + ": cannot write");
  }
  fs::rename(part, path);
}

}  // namespace tessera
