// The model-script interpreter: one command a line, in the spirit of UDEC's data files.
//
// Every command is documented in docs/commands.md. Errors are reported as "file:line: message"
// naming the word at fault; the batch runner exits non-zero on the first one.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "tessera/core/checks.hpp"
#include "tessera/core/model.hpp"
#include "tessera/core/step.hpp"
#include "tessera/generation/cutting3.hpp"
#include "tessera/io/figure.hpp"
#include "tessera/io/vtk_output.hpp"

namespace tessera {

class ScriptError : public std::runtime_error {
 public:
  ScriptError(const std::string& file, int line, const std::string& message)
      : std::runtime_error(file + ":" + std::to_string(line) + ": " + message),
        file_(file),
        line_(line),
        message_(message) {}
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  int line_;
  std::string message_;
};

// " (did you mean 'x'?)" for the closest option, or empty.
std::string suggest(const std::string& word, const std::vector<std::string>& options);

// What a batch run did, for the summary file.
struct RunSummary {
  uint64_t cycles_run = 0;
  double wall_seconds = 0.0;  // time spent cycling
  std::vector<std::string> warnings;
  std::optional<double> fos;  // the last `solve fos`
  // How the run ended: "completed", "error" (with the message) or "interrupted".
  std::string status = "completed", error;
};

// A step or solve the script ran: the stages of an analysis, as the GUI lists them.
struct StageRecord {
  std::string command;  // the line as written
  std::string file;
  int line = 0;
  uint64_t first_cycle = 0, last_cycle = 0;
  bool converged = false;  // solve only
};

// One command line split into words; key=value words become keys.
struct NodeBox;
struct BoltProperties;

struct Args {
  std::string command;
  std::vector<std::string> words;
  std::vector<std::pair<std::string, std::string>> keys;
  std::vector<bool> used;
};

// A time history (`table`): values at increasing times, linear between them and constant
// beyond the first and last.
struct Table {
  std::vector<double> time, value;
  double at(double t) const;
};

// A command that follows a table in time (written with table=NAME): run again between cycles
// with its numbers times the table's value at the model's time, or, for loads that add up
// (boundary stress and pressure), times the value's change since it last ran.
struct TimedCommand {
  Args args;  // without table=
  std::string table, file;
  int line = 0;
  bool incremental = false;
  double applied = 0.0;  // the table's value it last ran at
};

// What commands change in an interpreter (the model, variables, title, stages, checks, the
// summary), kept to go back to: the GUI's undo. Output files already written stay.
struct SavePoint {
  Model model;
  std::map<std::string, double> vars;
  std::string title;
  std::vector<StageRecord> stages;
  RunSummary summary;
  CheckLimits limits;
  uint64_t vtk_interval = 0;
  bool overlap_checked = false, proceed_on_errors = false;
  std::map<std::string, Table> tables;
  std::vector<TimedCommand> timed;
};

class Interpreter {
 public:
  using Log = std::function<void(const std::string&)>;
  // out_dir: where output files go; log: receives progress and print lines.
  explicit Interpreter(std::string out_dir, Log log = {});

  // Runs a script file; throws ScriptError on the first error.
  void run_file(const std::string& path);
  // Runs one line of script text as if it stood at file:line.
  void execute(const std::string& text, const std::string& file = "<input>", int line = 1);
  // Writes the histories CSV, a final VTK snapshot and the run summary into the output folder.
  void finish();

  Model& model() { return model_; }
  const Model& model() const { return model_; }
  const RunSummary& summary() const { return summary_; }
  // Records how a run that stopped early ended ("error" or "interrupted", and why), for the
  // summary file that finish() writes.
  void set_outcome(const std::string& status, const std::string& message) {
    summary_.status = status, summary_.error = message;
  }
  const std::string& out_dir() const { return out_dir_; }
  // Value of a script variable; throws std::out_of_range if unknown.
  double variable(const std::string& name) const { return vars_.at(name); }
  // A flag another thread may set to stop a running step or solve.
  void set_stop_flag(std::atomic<bool>* flag) { stop_ = flag; }
  // Seconds between progress lines during a run (0: none).
  void set_progress_interval(double seconds) { progress_seconds_ = seconds; }
  // Called on the running thread after every cycle of a step or solve (the GUI takes its
  // snapshots and pauses here).
  void set_observer(std::function<void(const Model&)> observer) { observer_ = std::move(observer); }
  // Draws figures for the `figure` command; without one, `figure` is an error.
  void set_figure_sink(FigureSink sink) { figure_sink_ = std::move(sink); }
  // With rollback on, a command that fails leaves the model as it was before that command
  // (the GUI's promise: nothing the user made is lost to a bad line or a diverging run). Without
  // `runs`, a failing step or solve is not undone: a batch run's results then show the model
  // as it stood when the run stopped (the blocks that diverged, the histories to that cycle),
  // while a half-done cut or zoning never reaches them.
  void set_rollback(bool on, bool runs = true) { rollback_ = on, rollback_runs_ = runs; }
  const std::vector<StageRecord>& stages() const { return stages_; }
  const std::string& title() const { return title_; }
  // Defines (or replaces) a table; throws std::invalid_argument unless its times increase and
  // every number is finite.
  void set_table(const std::string& name, Table t);
  const std::map<std::string, Table>& tables() const { return tables_; }
  // A copy of everything commands change, and a return to one.
  SavePoint save_point() const;
  void restore(const SavePoint& p);

 private:
  using Handler = void (Interpreter::*)(Args&);
  static const std::map<std::string, Handler>& handlers();
  // The command table of 3D models: the shared commands, the 3D forms, and the 2D-only ones
  // answering that they are 2D only (commands3.cpp).
  static const std::map<std::string, Handler>& handlers3();

  // Command handlers (commands.cpp, run_commands.cpp).
  void cmd_title(Args&);
  void cmd_set(Args&);
  void cmd_print(Args&);
  void cmd_round(Args&);
  void cmd_tolerance(Args&);
  void cmd_threads(Args&);
  void cmd_material(Args&);
  void cmd_joint(Args&);
  void cmd_block(Args&);
  void cmd_group(Args&);
  void cmd_fix(Args&);
  void cmd_free(Args&);
  void cmd_velocity(Args&);
  void cmd_load(Args&);
  void cmd_gravity(Args&);
  void cmd_damping(Args&);
  void cmd_timestep(Args&);
  void cmd_step(Args&);
  void cmd_solve(Args&);
  void cmd_history(Args&);
  void cmd_vtk(Args&);
  void cmd_figure(Args&);
  void solve_fos(Args&);
  void cmd_model(Args&);
  void cmd_save(Args&);
  void cmd_restore(Args&);
  void cmd_call(Args&);
  void cmd_wall(Args&);
  void make_block(std::vector<Vec2> pts, Args& a);
  // Block generation (generation_commands.cpp).
  void cmd_region(Args&);
  void cmd_crack(Args&);
  void cmd_jset(Args&);
  void cmd_tunnel(Args&);
  void cmd_voronoi(Args&);
  void cmd_arch(Args&);
  void cmd_delete(Args&);
  void cmd_join(Args&);
  void cmd_check(Args&);
  // Rock support (support_commands.cpp).
  void cmd_bolt(Args&);
  BoltProperties bolt_properties(Args& a);
  // The support point a history of quantity q names: bolt=, cable= or liner=NAME [at=X,Y], the
  // crossing or node nearest the point (the first without at=); sets `name` to the member's.
  int32_t support_point(Args& a, HistoryQuantity q, std::string& name);
  // 'bolt pattern' and 'cable pattern': joints=OPENING spacing=S length=L [angles=A0,A1].
  struct Pattern {
    std::string joints;
    int tag = -1;
    double spacing = 0.0, length = 0.0, a0 = -180.0, a1 = 180.0;
  };
  Pattern pattern_args(Args& a, const std::string& what);
  void cmd_cable(Args&);
  void cmd_liner(Args&);
  CableProperties cable_properties(Args& a);
  // Deformable blocks (zone_commands.cpp).
  void cmd_zone(Args&);
  void cmd_boundary(Args&);
  void cmd_insitu(Args&);
  void cmd_reset(Args&);
  // Tables and the commands that follow them (table_commands.cpp).
  void cmd_table(Args&);
  // Takes table=NAME off a command, runs it at the table's present value and keeps it to run
  // between cycles; false when the command has no table=.
  bool follow_table(const Args& a);
  // Runs a timed command with its numbers times `scale`.
  void run_scaled(const TimedCommand& t, double scale);
  // Runs again the timed commands whose table's value has changed (between two cycles).
  void apply_tables();
  // 3D models (commands3.cpp).
  void cmd_dimension(Args&);
  void cmd_block3(Args&);
  void cmd_region3(Args&);
  void cmd_crack3(Args&);
  void cmd_jset3(Args&);
  void cmd_tunnel3(Args&);
  void cmd_wall3(Args&);
  void cmd_fix3(Args&);
  void cmd_velocity3(Args&);
  void cmd_gravity3(Args&);
  void cmd_delete3(Args&);
  void cmd_join3(Args&);
  void cmd_only2d(Args&);
  Vec3 point3(const std::string& text) const;
  // A box of nodes and zones: x=X0,X1 y=Y0,Y1 (and z=Z0,Z1 in 3D), each optional.
  NodeBox node_box(Args& a);
  // Boundary stress on the deformable blocks' outline edges (2D) or surface triangles (3D) in the
  // box (along joints of `tag` if not -1); returns how many took it.
  size_t boundary_stress2(const NodeBox& box, const ZoneStress& s, int tag);
  size_t boundary_stress3(const NodeBox& box, const ZoneStress& s, int tag);
  // Fixity bits named by the words of 'fix' and 'free' (all when none is named).
  uint8_t fixity_words(const std::vector<std::string>& words) const;
  // The keywords both walls share (courses=, bricks=, group=, material=, name=, made into the
  // bed and head joint tags); finishes the keywords.
  struct WallLayout {
    int courses = 0, bricks = 0, group = -1, material = -1, bed_tag = -1, head_tag = -1;
  };
  WallLayout wall_layout(Args& a);
  // Group and material keywords of a new block (group=, material=).
  std::pair<int, int> group_material(Args& a);
  // Cuts the selection (all when none is given) by planes named `name`.
  void cut3(Args& a, std::vector<JointPlane> planes, const std::string& what);
  // The rest of a cutting command's line: the selection if `selectable` (all blocks if none),
  // refused where it holds a piece of a joined block.
  std::vector<size_t> cut_selection3(Args& a, bool selectable = true);
  // Runs the geometry checks; errors fail unless the script said to go on.
  void run_checks(bool before_run);
  // A mean and optional standard deviation written as MEAN or MEAN,SD.
  std::pair<double, double> mean_sd(const std::string& text) const;
  std::vector<size_t> optional_selection(Args& a);
  // What a cut acts on: its joint name (`kind` and a number unless name= is given), the
  // selection (empty: all blocks), the blocks themselves and their box. Finishes the keywords.
  struct CutTarget {
    std::string name;
    std::vector<size_t> selection, blocks;
    Vec2 lo, hi;
  };
  CutTarget cut_target(Args& a, const std::string& kind);

  // Argument helpers (script.cpp).
  [[noreturn]] void fail(const std::string& message) const;
  double num(const std::string& text) const;
  Vec2 point(const std::string& text) const;
  int64_t integer(const std::string& text, int64_t min) const;
  bool take(Args& a, const std::string& key, std::string& value) const;
  bool take_num(Args& a, const std::string& key, double& value) const;
  void done(Args& a) const;  // fails on keys no handler used
  // Fails saying `what` needs `key=`, naming a mistyped key if there is one.
  [[noreturn]] void missing(const Args& a, const std::string& key, const std::string& what) const;
  std::vector<size_t> select(Args& a, bool allow_words = false);
  // The block holding the point X,Y (X,Y,Z), or the nearest within the contact tolerance.
  size_t block_at(const std::string& text) const;
  // The same at a point of the model's dimension (`shown`: how messages write it).
  size_t block_at(const std::vector<double>& xyz, const std::string& shown) const;
  // A block's number as users see it, and the index of the block with a number (-1: none).
  int block_id(size_t b) const;
  int64_t block_index(int64_t id) const;
  std::string resolve(const std::string& path, bool for_reading) const;
  void run_with_progress(const std::function<bool(const Progress&)>& body, const std::string& what);
  void check_ready();
  void log(const std::string& s) const;
  // Logs a warning at the current file:line and keeps it for summary.json.
  void warn(const std::string& message);
  // Warns when the histories would grow past ~100 MB of CSV over the next `cycles` cycles.
  void warn_history_size(uint64_t cycles);

  Model model_;
  std::map<std::string, double> vars_;
  std::string out_dir_;
  Log log_;
  std::unique_ptr<VtkSeries> vtk_;
  uint64_t vtk_interval_ = 0;
  std::string title_;
  std::vector<std::string> dir_stack_{"."};
  std::string file_ = "<input>";
  int line_ = 0;
  int call_depth_ = 0;
  bool overlap_checked_ = false;
  bool far_warned_ = false;  // that the model lies too far from the origin
  CheckLimits limits_;
  bool proceed_on_errors_ = false;
  std::atomic<bool>* stop_ = nullptr;
  std::function<void(const Model&)> observer_;
  FigureSink figure_sink_;
  bool rollback_ = false, rollback_runs_ = true;
  std::vector<StageRecord> stages_;
  std::string text_;  // the line being run
  double progress_seconds_ = 2.0;
  RunSummary summary_;
  std::map<std::string, Table> tables_;
  std::vector<TimedCommand> timed_;
  friend struct ScriptAccess;
};

}  // namespace tessera
