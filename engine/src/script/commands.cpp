// Script commands that build a model: geometry, groups, properties, conditions, settings.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>

#include "tessera/core/parallel.hpp"
#include "tessera/generation/generators.hpp"
#include "tessera/generation/generators3.hpp"
#include "tessera/plugin.hpp"
#include "tessera/script/expr.hpp"
#include "tessera/script/script.hpp"
#include "tessera/zones/deformable.hpp"

namespace tessera {

const std::map<std::string, Interpreter::Handler>& Interpreter::handlers() {
  static const std::map<std::string, Handler> h{
      {"title", &Interpreter::cmd_title},       {"dimension", &Interpreter::cmd_dimension},
      {"set", &Interpreter::cmd_set},           {"print", &Interpreter::cmd_print},
      {"round", &Interpreter::cmd_round},       {"tolerance", &Interpreter::cmd_tolerance},
      {"threads", &Interpreter::cmd_threads},   {"material", &Interpreter::cmd_material},
      {"joint", &Interpreter::cmd_joint},       {"block", &Interpreter::cmd_block},
      {"group", &Interpreter::cmd_group},       {"fix", &Interpreter::cmd_fix},
      {"free", &Interpreter::cmd_free},         {"velocity", &Interpreter::cmd_velocity},
      {"gravity", &Interpreter::cmd_gravity},   {"damping", &Interpreter::cmd_damping},
      {"timestep", &Interpreter::cmd_timestep}, {"step", &Interpreter::cmd_step},
      {"solve", &Interpreter::cmd_solve},       {"history", &Interpreter::cmd_history},
      {"vtk", &Interpreter::cmd_vtk},           {"figure", &Interpreter::cmd_figure},
      {"save", &Interpreter::cmd_save},         {"restore", &Interpreter::cmd_restore},
      {"call", &Interpreter::cmd_call},         {"wall", &Interpreter::cmd_wall},
      {"region", &Interpreter::cmd_region},     {"crack", &Interpreter::cmd_crack},
      {"jset", &Interpreter::cmd_jset},         {"tunnel", &Interpreter::cmd_tunnel},
      {"voronoi", &Interpreter::cmd_voronoi},   {"arch", &Interpreter::cmd_arch},
      {"delete", &Interpreter::cmd_delete},     {"join", &Interpreter::cmd_join},
      {"check", &Interpreter::cmd_check},       {"reset", &Interpreter::cmd_reset},
      {"zone", &Interpreter::cmd_zone},         {"boundary", &Interpreter::cmd_boundary},
      {"insitu", &Interpreter::cmd_insitu},     {"model", &Interpreter::cmd_model},
      {"bolt", &Interpreter::cmd_bolt},         {"cable", &Interpreter::cmd_cable},
      {"liner", &Interpreter::cmd_liner},       {"table", &Interpreter::cmd_table},
      {"load", &Interpreter::cmd_load},
  };
  return h;
}

void Interpreter::cmd_model(Args& a) {
  if (a.words.size() != 2 || a.words[0] != "load")
    fail("write 'model load FILE.so' (a plug-in of joint laws or zone models)");
  done(a);
  const std::string path = resolve(a.words[1], true);
  std::vector<std::string> names;
  try {
    names = load_plugin(path);
  } catch (const std::runtime_error& e) {
    fail(e.what());
  }
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  log(names.empty() ? "model load: " + path + " is loaded already" : "model load: " + list);
}

void Interpreter::cmd_reset(Args& a) {
  if (a.words.size() != 1 || a.words[0] != "displacement") fail("write 'reset displacement'");
  done(a);
  // Displacements count from here: after the in-situ equilibrium, say (2D and 3D blocks: a
  // concave 3D body's from its master's reference; zone nodes). Rotations stay as they were.
  Blocks& B = model_.blocks;
  B.x_ref = B.x, B.y_ref = B.y;
  Blocks3& B3 = model_.blocks3;
  for (size_t b = 0; b < B3.size(); ++b) B3.ref[b] = B3.body[b].position;
  model_.continuum.pos0 = model_.continuum.pos;
  model_.continuum3.pos0 = model_.continuum3.pos;
  log("reset: displacements are zero from cycle " + std::to_string(model_.cycle));
}

void Interpreter::cmd_title(Args& a) {
  std::string t;
  for (const auto& w : a.words) t += (t.empty() ? "" : " ") + w;
  title_ = t;
  if (!title_.empty() && title_.front() == '"' && title_.back() == '"' && title_.size() > 1)
    title_ = title_.substr(1, title_.size() - 2);
}

void Interpreter::cmd_set(Args& a) {
  if (a.words.size() < 3 || a.words[1] != "=")
    fail("write 'set NAME = EXPRESSION' (with spaces around '=')");
  const std::string& name = a.words[0];
  if (!std::isalpha(static_cast<unsigned char>(name[0])) ||
      !std::all_of(name.begin(), name.end(),
                   [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }))
    fail("'" + name + "' is not a variable name (letters, digits and _, starting with a letter)");
  std::string expr;
  for (size_t i = 2; i < a.words.size(); ++i) expr += a.words[i] + " ";
  vars_[name] = num(expr);
}

void Interpreter::cmd_print(Args& a) {
  std::string out;
  for (const auto& w : a.words) {
    if (w.size() >= 2 && w.front() == '"' && w.back() == '"') {
      out += w.substr(1, w.size() - 2);
    } else {
      std::ostringstream s;
      s.precision(10);
      s << num(w);
      out += s.str();
    }
    out += ' ';
  }
  for (const auto& [k, v] : a.keys) {
    std::ostringstream s;
    s.precision(10);
    s << k << " = " << num(v) << ' ';
    out += s.str();
  }
  a.used.assign(a.keys.size(), true);
  log(out);
}

void Interpreter::cmd_round(Args& a) {
  if (a.words.size() != 1) fail("write 'round D' with the rounding length D");
  const double d = num(a.words[0]);
  if (d <= 0.0) fail("the rounding length must be positive");
  if (!model_.blocks.size()) {
    model_.settings.rounding = d;
    return;
  }
  fail("set 'round' before the first block: corners are rounded when a block is made");
}

void Interpreter::cmd_tolerance(Args& a) {
  if (a.words.size() != 1) fail("write 'tolerance T' with the contact tolerance T");
  const double t = num(a.words[0]);
  if (t <= 0.0) fail("the contact tolerance must be positive");
  model_.settings.contact_tolerance = t;
  model_.touch();
}

void Interpreter::cmd_threads(Args& a) {
  if (a.words.size() != 1) fail("write 'threads N'");
  set_thread_count(static_cast<int>(integer(a.words[0], 1)));
}

void Interpreter::cmd_material(Args& a) {
  if (a.words.size() < 2)
    fail("write 'material define NAME density=RHO' or 'material assign NAME <blocks>'");
  const std::string verb = a.words[0], name = a.words[1];
  a.words.erase(a.words.begin(), a.words.begin() + 2);
  if (verb == "define") {
    double rho = 0.0;
    if (!take_num(a, "density", rho)) missing(a, "density", "material '" + name + "'");
    if (rho <= 0.0) fail("the density of material '" + name + "' must be positive");
    // Zone constants for deformable blocks: E and nu, or K and G; a plasticity model.
    ZoneProperties zone;
    zone.name = name;
    zone.density = rho;
    double young = 0, poisson = 0;
    const bool has_e = take_num(a, "E", young), has_nu = take_num(a, "nu", poisson);
    const bool has_k = take_num(a, "K", zone.bulk), has_g = take_num(a, "G", zone.shear);
    std::string model = "elastic";
    take(a, "model", model);
    take_num(a, "friction", zone.friction), take_num(a, "cohesion", zone.cohesion);
    take_num(a, "tension", zone.tension), take_num(a, "dilation", zone.dilation);
    // Strain-softening tables: strain,value pairs of the plastic shear strain.
    bool has_table = false;
    for (auto [key, table] :
         {std::pair{"ctable", &zone.ctable}, std::pair{"ftable", &zone.ftable},
          std::pair{"dtable", &zone.dtable}, std::pair{"ttable", &zone.ttable}}) {
      std::string v;
      if (!take(a, key, v)) continue;
      has_table = true;
      for (const auto& part : split_top_level(v)) table->push_back(num(part));
      if (table->size() % 2 != 0)
        fail("material '" + name + "': " + key + " needs pairs strain,value (" +
             std::to_string(table->size()) + " numbers given)");
    }
    // A plane of weakness and its orientation (also the plane of transverse isotropy).
    const bool has_jfriction = take_num(a, "jfriction", zone.jfriction);
    bool has_joint = has_jfriction;
    has_joint |= take_num(a, "jcohesion", zone.jcohesion);
    has_joint |= take_num(a, "jtension", zone.jtension);
    has_joint |= take_num(a, "jdilation", zone.jdilation);
    const bool has_angle = take_num(a, "jangle", zone.jangle);
    const bool has_dip = take_num(a, "jdip", zone.jdip),
               has_dd = take_num(a, "jdipdir", zone.jdipdir);
    if (has_angle && (has_dip || has_dd))
      fail("material '" + name + "': give jangle= (2D) or jdip= and jdipdir= (3D), not both");
    if (has_dip != has_dd) fail("material '" + name + "' needs both jdip= and jdipdir=");
    zone.orientation = has_angle ? 2 : has_dip ? 3 : 0;
    // Transversely isotropic constants.
    bool has_ti = false;
    std::string ti_missing;
    for (auto [key, value] :
         {std::pair{"E1", &zone.e1}, std::pair{"E3", &zone.e3}, std::pair{"nu12", &zone.nu12},
          std::pair{"nu13", &zone.nu13}, std::pair{"G13", &zone.g13}}) {
      if (take_num(a, key, *value))
        has_ti = true;
      else if (ti_missing.empty())
        ti_missing = key;
    }
    done(a);
    if (has_table && model != "strain-softening")
      fail("material '" + name + "': ctable, ftable, dtable and ttable belong to " +
           "model=strain-softening");
    if (has_joint && model != "ubiquitous-joint")
      fail("material '" + name + "': jfriction, jcohesion, jtension and jdilation belong to " +
           "model=ubiquitous-joint");
    if (zone.orientation && model != "ubiquitous-joint" && model != "transversely-isotropic")
      fail("material '" + name + "': jangle, jdip and jdipdir belong to model=ubiquitous-joint " +
           "and model=transversely-isotropic");
    if (zone.orientation && zone.orientation != model_.dim)
      fail("material '" + name + "': a " + std::to_string(model_.dim) + "D model's plane is " +
           (model_.dim == 3 ? "jdip= and jdipdir=" : "jangle=") +
           " (write 'dimension 3' before a 3D model's materials)");
    if (has_ti && model != "transversely-isotropic")
      fail("material '" + name + "': E1, E3, nu12, nu13 and G13 belong to " +
           "model=transversely-isotropic");
    if (model == "transversely-isotropic") {
      if (has_e || has_nu || has_k || has_g)
        fail("material '" + name + "': model=transversely-isotropic takes E1, E3, nu12, nu13 " +
             "and G13, not E and nu or K and G");
      if (!ti_missing.empty())
        fail("material '" + name + "' (transversely-isotropic) needs " + ti_missing + "=");
    }
    if (model == "ubiquitous-joint" && !has_jfriction)
      fail("material '" + name + "' (ubiquitous-joint) needs jfriction=");
    if (has_e || has_nu || has_k || has_g || has_ti) {
      if ((has_e || has_nu) && (has_k || has_g)) fail("give E and nu, or K and G, not both pairs");
      if (has_e != has_nu) fail("material '" + name + "' needs both E and nu");
      if (has_k != has_g) fail("material '" + name + "' needs both K and G");
      zone.model = model;
      try {
        if (has_e) elastic_from_young(young, poisson, zone.bulk, zone.shear);
        zone.finalize();
      } catch (const std::invalid_argument& e) {
        // (A misspelt model name gets a suggestion; a bad constant or strength only the reason.)
        std::string why = e.what();
        const std::string named = "zone material '" + name + "': ";
        if (why.rfind(named, 0) == 0) why = why.substr(named.size());  // named once, below
        fail("material '" + name + "': " + why +
             (why.find("is not a zone model") != std::string::npos
                  ? suggest(model, zone_model_names())
                  : ""));
      }
    } else {
      zone.model.clear();
    }
    int k = model_.material_index(name);
    if (k < 0)
      model_.materials.push_back({name, rho, zone}),
          k = static_cast<int>(model_.materials.size()) - 1;
    model_.materials[static_cast<size_t>(k)].density = rho;
    model_.materials[static_cast<size_t>(k)].zone = zone;
    for (size_t b = 0; b < model_.blocks.size(); ++b)
      if (model_.blocks.material[b] == k) model_.blocks.set_density(b, rho);
    for (size_t b = 0; b < model_.blocks3.size(); ++b)
      if (model_.blocks3.material[b] == k) model_.blocks3.set_density(b, rho);
    if (model_.continuum.zone_count() > 0) {
      sync_zone_materials(model_);
      lump_masses(model_.continuum);
    }
    model_.touch();
  } else if (verb == "assign") {
    const int k = model_.material_index(name);
    if (k < 0) {
      std::vector<std::string> names;
      for (const auto& m : model_.materials) names.push_back(m.name);
      fail("there is no material '" + name + "'" + suggest(name, names));
    }
    const auto sel = select(a);
    done(a);
    const double rho_k = model_.materials[static_cast<size_t>(k)].density;
    // The pieces of joined 3D bodies, whose mass and inertia come from their densities at the
    // join.
    const Blocks3& B3 = model_.blocks3;
    std::vector<uint8_t> joined(B3.size(), 0);
    for (size_t b = 0; b < B3.size(); ++b)
      if (B3.is_slave(b)) joined[b] = joined[static_cast<size_t>(B3.master[b])] = 1;
    for (size_t b : sel) {
      if (model_.dim == 3) {
        if (joined[b]) {
          if (B3.material[b] == k) continue;
          fail("block " + std::to_string(B3.id[b]) +
               " is a piece of a joined body: assign materials before joining");
        }
        model_.blocks3.material[b] = k, model_.blocks3.set_density(b, rho_k);
        continue;
      }
      model_.blocks.material[b] = k;
      model_.blocks.set_density(b, rho_k);
    }
    model_.touch();
  } else {
    fail("'" + verb + "' is not a verb of 'material' (define or assign)");
  }
}

void Interpreter::cmd_joint(Args& a) {
  if (a.words.size() < 2)
    fail("write 'joint define NAME kn=.. ks=.. friction=..' or 'joint assign NAME'");
  const std::string verb = a.words[0], name = a.words[1];
  if (a.words.size() > 2) fail("unexpected word '" + a.words[2] + "'");
  if (verb == "define") {
    JointProperties j;
    j.name = name;
    const int existing = model_.joint_index(name);
    if (existing >= 0) j = model_.joints[static_cast<size_t>(existing)];
    const bool fresh = existing < 0;
    auto need = [&](const char* key, double& v) {
      if (!take_num(a, key, v) && fresh) missing(a, key, "joint '" + name + "'");
    };
    take(a, "law", j.law);
    const bool cy = j.law == "cy", bb = j.law == "barton-bandis";
    need("kn", j.kn);
    need("ks", j.ks);
    need("friction", j.friction);
    const bool nonlinear_keys = take_num(a, "en", j.en) | take_num(a, "es", j.es) |
                                take_num(a, "sref", j.sref) | take_num(a, "smax", j.smax) |
                                take_num(a, "ifriction", j.initial_friction) |
                                take_num(a, "roughness", j.roughness);
    const bool has_jrc = take_num(a, "jrc", j.jrc), has_jcs = take_num(a, "jcs", j.jcs);
    const bool has_vm = take_num(a, "vm", j.vm);
    const bool bb_keys = has_jrc | has_jcs | has_vm | take_num(a, "dpeak", j.dpeak) |
                         take_num(a, "lj", j.lj) | take_num(a, "knmax", j.kn_cap);
    if (bb && fresh) {
      const std::string what = "joint '" + name + "' (law=barton-bandis)";
      if (!has_jrc) missing(a, "jrc", what);
      if (!has_jcs) missing(a, "jcs", what);
      if (!has_vm) missing(a, "vm", what);
    }
    take_num(a, "cohesion", j.cohesion);
    take_num(a, "tension", j.tension);
    take_num(a, "dilation", j.dilation);
    take_num(a, "dilation_limit", j.dilation_limit);
    take_num(a, "rfriction", j.residual_friction);
    take_num(a, "rcohesion", j.residual_cohesion);
    take_num(a, "ndamping", j.normal_damping);
    take_num(a, "sdamping", j.shear_damping);
    done(a);
    if (j.kn <= 0.0 || j.ks <= 0.0) fail("joint '" + name + "': kn and ks must be positive");
    if (j.friction < 0.0 || j.friction >= 90.0)
      fail("joint '" + name + "': friction must be in [0, 90) degrees");
    if (j.dilation < 0.0 || j.dilation >= 90.0)
      fail("joint '" + name + "': dilation must be in [0, 90) degrees");
    if (j.cohesion < 0.0 || j.tension < 0.0 || j.dilation_limit < 0.0)
      fail("joint '" + name + "': cohesion, tension and dilation_limit cannot be negative");
    if (!(j.normal_damping >= 0.0 && j.normal_damping < 1.0 && j.shear_damping >= 0.0 &&
          j.shear_damping < 1.0))
      fail("joint '" + name + "': ndamping and sdamping are fractions of critical, in [0, 1)");
    if (j.residual_friction >= 90.0 || j.residual_cohesion < 0.0)
      fail("joint '" + name + "': rfriction must be below 90 degrees and rcohesion not negative");
    if (j.law != "coulomb-residual" && (j.residual_friction >= 0.0 || j.residual_cohesion > 0.0))
      fail("joint '" + name + "': rfriction and rcohesion belong to law=coulomb-residual");
    if (nonlinear_keys && !cy)
      fail("joint '" + name + "': en, es, sref, smax, ifriction and roughness belong to law=cy");
    if (bb_keys && !bb)
      fail("joint '" + name + "': jrc, jcs, vm, dpeak, lj and knmax belong to law=barton-bandis");
    if ((cy || bb) && (j.cohesion > 0.0 || j.tension > 0.0 || j.dilation > 0.0))
      fail("joint '" + name + "': law=" + j.law +
           " has no cohesion, tension or dilation parameter (its dilation comes from roughness)");
    if (!find_joint_law(j.law))
      fail("'" + j.law + "' is not a joint law" + suggest(j.law, joint_law_names()));
    j.finalize();
    if (fresh)
      model_.joints.push_back(j);
    else
      model_.joints[static_cast<size_t>(existing)] = j;
    model_.dt_dirty = true;
  } else if (verb == "assign") {
    const int k = model_.joint_index(name);
    if (k < 0) {
      std::vector<std::string> names;
      for (const auto& j : model_.joints) names.push_back(j.name);
      fail("there is no joint '" + name + "' (define it first with 'joint define')" +
           suggest(name, names));
    }
    JointAssignment ja;
    ja.joint = static_cast<uint32_t>(k);
    std::string groups;
    if (take(a, "groups", groups)) {
      const auto g = split_top_level(groups);
      if (g.size() != 2) fail("write groups=A,B with two group names");
      ja.group_a = model_.group_index(g[0], false);
      ja.group_b = model_.group_index(g[1], false);
      for (int i = 0; i < 2; ++i)
        if ((i ? ja.group_b : ja.group_a) < 0)
          fail("there is no group '" + g[static_cast<size_t>(i)] + "'" +
               suggest(g[static_cast<size_t>(i)], model_.groups));
    }
    std::string joints;
    if (take(a, "joints", joints)) {
      ja.tag = -1;
      for (size_t t = 0; t < model_.joint_tags.size(); ++t)
        if (model_.joint_tags[t] == joints) ja.tag = static_cast<int>(t);
      if (ja.tag < 0)
        fail("there are no joints named '" + joints + "'" + suggest(joints, model_.joint_tags));
    }
    done(a);
    model_.joint_table.push_back(ja);
    // Existing contacts take the new properties at once.
    for (size_t i = 0; i < model_.contacts.size(); ++i) {
      const int j =
          model_.joint_for(model_.contacts.a[i], model_.contacts.b[i], model_.contacts.tag[i]);
      if (j >= 0) model_.contacts.joint[i] = static_cast<uint32_t>(j);
    }
    for (Contact3& c : model_.contacts3)
      if (const int j = model_.joint_for(c.a, c.b, c.tag); j >= 0)
        c.joint = static_cast<uint32_t>(j);
    model_.touch();
  } else {
    fail("'" + verb + "' is not a verb of 'joint' (define or assign)");
  }
}

void Interpreter::cmd_block(Args& a) {
  std::vector<Vec2> pts;
  for (const auto& w : a.words) pts.push_back(point(w));
  make_block(pts, a);
}

void Interpreter::make_block(std::vector<Vec2> pts, Args& a) {
  if (model_.settings.rounding <= 0.0)
    fail("set the rounding length with 'round D' before the first block");
  const std::string which = "block " + std::to_string(model_.blocks.size() + 1);
  if (const std::string why = polygon_problem(pts); !why.empty()) fail(which + ": " + why);
  if (signed_area(pts) < 0.0) std::reverse(pts.begin(), pts.end());
  std::string g, mat;
  int group = -1, material = -1;
  if (take(a, "group", g)) group = model_.group_index(g, true);
  if (take(a, "material", mat)) {
    material = model_.material_index(mat);
    if (material < 0) {
      std::vector<std::string> names;
      for (const auto& m : model_.materials) names.push_back(m.name);
      fail(which + ": there is no material '" + mat + "' (define it first)" + suggest(mat, names));
    }
  }
  done(a);
  const double rho = material >= 0 ? model_.materials[static_cast<size_t>(material)].density : 0.0;
  model_.blocks.add(pts, model_.settings.rounding, rho, group, material);
  model_.touch();
  overlap_checked_ = false;
}

void Interpreter::cmd_wall(Args& a) {
  if (model_.settings.rounding <= 0.0)
    fail("set the rounding length with 'round D' before the first block");
  if (!a.words.empty()) fail("unexpected word '" + a.words[0] + "'");
  WallSpec w;
  std::string v;
  if (take(a, "origin", v)) w.origin = point(v);
  if (!take(a, "brick", v)) missing(a, "brick", "'wall'");
  const Vec2 brick = point(v);
  w.brick_length = brick.x(), w.brick_height = brick.y();
  if (w.brick_length <= 0.0 || w.brick_height <= 0.0) fail("brick sizes must be positive");
  const WallLayout l = wall_layout(a);
  w.courses = l.courses, w.bricks = l.bricks, w.group = l.group, w.material = l.material;
  w.bed_tag = l.bed_tag, w.head_tag = l.head_tag;
  add_running_bond_wall(model_, w);
  overlap_checked_ = false;
}

Interpreter::WallLayout Interpreter::wall_layout(Args& a) {
  WallLayout l;
  std::string v;
  if (!take(a, "courses", v)) missing(a, "courses", "'wall'");
  l.courses = static_cast<int>(std::min<int64_t>(integer(v, 1), 1 << 30));
  if (!take(a, "bricks", v)) missing(a, "bricks", "'wall' (bricks per course)");
  l.bricks = static_cast<int>(std::min<int64_t>(integer(v, 1), 1 << 30));
  if (static_cast<double>(l.courses) * l.bricks > 1e6)
    fail("a wall of more than a million bricks is not supported");
  std::tie(l.group, l.material) = group_material(a);
  // Bed and head joints are named for assigning mortar properties: NAME_bed, NAME_head.
  std::string name = "wall";
  take(a, "name", name);
  done(a);
  l.bed_tag = joint_tag(model_, name + "_bed");
  l.head_tag = joint_tag(model_, name + "_head");
  return l;
}

void Interpreter::cmd_group(Args& a) {
  if (a.words.empty()) fail("write 'group NAME <blocks>'");
  const std::string name = a.words[0];
  a.words.erase(a.words.begin());
  const auto sel = select(a);
  done(a);
  const int g = model_.group_index(name, true);
  for (size_t b : sel) (model_.dim == 3 ? model_.blocks3.group : model_.blocks.group)[b] = g;
  model_.touch();
}

// Fixity bits named by the words x, y (z), rotation; all of them when none is named.
uint8_t Interpreter::fixity_words(const std::vector<std::string>& words) const {
  const bool three = model_.dim == 3;
  const std::vector<std::pair<std::string, uint8_t>> names =
      three ? std::vector<std::pair<std::string, uint8_t>>{{"x", kFix3X},
                                                           {"y", kFix3Y},
                                                           {"z", kFix3Z},
                                                           {"rotation", kFix3Rot}}
            : std::vector<std::pair<std::string, uint8_t>>{
                  {"x", kFixX}, {"y", kFixY}, {"rotation", kFixRot}};
  uint8_t bits = 0;
  for (const auto& w : words) {
    const auto it =
        std::find_if(names.begin(), names.end(), [&](const auto& n) { return n.first == w; });
    if (it == names.end())
      fail("'" + w + "' is not a degree of freedom (" + (three ? "x, y, z" : "x, y") +
           " or rotation)");
    bits |= it->second;
  }
  const uint8_t all = three ? uint8_t{kFix3All} : uint8_t{kFixAll};
  return bits ? bits : all;
}

void Interpreter::cmd_fix(Args& a) {
  const auto sel = select(a, true);
  done(a);
  const uint8_t bits = fixity_words(a.words);
  for (size_t b : sel) {
    // A deformable block moves with its nodes: they are held (at their velocity now).
    if (model_.blocks.deformable[b]) {
      if (!(bits & (kFixX | kFixY)))
        fail("block " + std::to_string(model_.blocks.id[b]) +
             " is deformable: its nodes have no rotation to fix (fix x, y or both)");
      set_block_nodes(model_, b, bits & (kFixX | kFixY), false, nullptr);
      continue;
    }
    model_.blocks.fixity[b] |= bits;
    // A degree of freedom is held at the velocity it has now unless 'velocity' says otherwise.
    if (bits & kFixX) model_.blocks.fixed_vx[b] = model_.blocks.vx[b];
    if (bits & kFixY) model_.blocks.fixed_vy[b] = model_.blocks.vy[b];
    if (bits & kFixRot) model_.blocks.fixed_omega[b] = model_.blocks.omega[b];
  }
  model_.touch();
}

void Interpreter::cmd_free(Args& a) {
  const auto sel = select(a, true);
  done(a);
  const uint8_t bits = fixity_words(a.words);
  const bool three = model_.dim == 3;
  auto& fixity = three ? model_.blocks3.fixity : model_.blocks.fixity;
  const auto& deformable = three ? model_.blocks3.deformable : model_.blocks.deformable;
  const uint8_t moves = three ? uint8_t(kFix3X | kFix3Y | kFix3Z) : uint8_t(kFixX | kFixY);
  std::vector<size_t> rigid;
  for (size_t b : sel) {
    // A deformable block's nodes (its own fixity stays: its body does not move).
    if (deformable[b])
      set_block_nodes(model_, b, bits & moves, true, nullptr);
    else
      rigid.push_back(b);
  }
  // (A piece of a joined 3D body frees the whole body.)
  for (size_t b : three ? whole_bodies3(model_.blocks3, rigid) : rigid)
    fixity[b] &= static_cast<uint8_t>(~bits);
  model_.touch();
}

void Interpreter::cmd_velocity(Args& a) {
  const auto sel = select(a);
  double vx = 0, vy = 0, om = 0;
  const bool hx = take_num(a, "vx", vx), hy = take_num(a, "vy", vy), hw = take_num(a, "omega", om);
  done(a);
  if (!hx && !hy && !hw) fail("'velocity' needs vx=, vy= or omega=");
  // A fixed degree of freedom takes its new velocity at the next integration: the velocity of
  // the last half step stays, since the next cycle's joint increments are the motion it made.
  // A free one starts from the velocity given.
  Blocks& B = model_.blocks;
  for (size_t b : sel) {
    if (B.deformable[b]) {
      // Its nodes: held ones take the velocity at the next step, free ones start with it.
      if (hw && !hx && !hy)
        fail("block " + std::to_string(B.id[b]) + " is deformable: give its nodes vx= or vy=");
      const double v[2] = {vx, vy};
      set_block_nodes(model_, b, 0, false, v,
                      static_cast<uint8_t>((hx ? kFixX : 0) | (hy ? kFixY : 0)));
      continue;
    }
    const uint8_t fix = B.fixity[b];
    if (hx) B.fixed_vx[b] = vx, B.vx[b] = (fix & kFixX) ? B.vx[b] : vx;
    if (hy) B.fixed_vy[b] = vy, B.vy[b] = (fix & kFixY) ? B.vy[b] : vy;
    if (hw) B.fixed_omega[b] = om, B.omega[b] = (fix & kFixRot) ? B.omega[b] : om;
  }
}

void Interpreter::cmd_gravity(Args& a) {
  if (a.words.size() != 2) fail("write 'gravity GX GY' (m/s^2), e.g. 'gravity 0 -9.81'");
  model_.settings.gravity = Vec2(num(a.words[0]), num(a.words[1]));
}

void Interpreter::cmd_damping(Args& a) {
  if (a.words.empty())
    fail(
        "write 'damping local [ALPHA]', 'damping kinetic [ALPHA]', 'damping global [RATIO]' or "
        "'damping none'");
  Settings& s = model_.settings;
  const std::string& mode = a.words[0];
  if (a.words.size() > 2) fail("unexpected word '" + a.words[2] + "'");
  const bool has = a.words.size() == 2;
  if (mode == "local") {
    s.damping = DampingMode::kLocal;
    if (has) s.local_alpha = num(a.words[1]);
    if (s.local_alpha < 0.0 || s.local_alpha >= 1.0) fail("local damping alpha must be in [0, 1)");
  } else if (mode == "global") {
    s.damping = DampingMode::kAdaptiveGlobal;
    if (has) s.global_ratio = num(a.words[1]);
    if (s.global_ratio <= 0.0 || s.global_ratio >= 1.0)
      fail("the global damping ratio must be in (0, 1)");
  } else if (mode == "kinetic") {
    s.damping = DampingMode::kKinetic;
    if (has) s.kinetic_alpha = num(a.words[1]);
    if (s.kinetic_alpha < 0.0 || s.kinetic_alpha >= 1.0)
      fail("kinetic damping's alpha must be in [0, 1)");
  } else if (mode == "none") {
    if (has) fail("'damping none' takes no value");
    s.damping = DampingMode::kNone;
  } else {
    fail("'" + mode + "' is not a damping mode" +
         suggest(mode, {"local", "kinetic", "global", "none"}));
  }
}

void Interpreter::cmd_timestep(Args& a) {
  if (a.words.empty())
    fail("write 'timestep auto [safety=S]', 'timestep scaled [safety=S]' or 'timestep fixed DT'");
  Settings& s = model_.settings;
  if (a.words[0] == "auto" || a.words[0] == "scaled") {
    if (a.words.size() > 1) fail("unexpected word '" + a.words[1] + "'");
    take_num(a, "safety", s.dt_safety);
    done(a);
    if (s.dt_safety <= 0.0 || s.dt_safety > 1.0)
      fail("the time step safety factor must be in (0, 1]");
    s.dt_fixed = 0.0;
    s.dt_scaled = a.words[0] == "scaled";
  } else if (a.words[0] == "fixed") {
    if (a.words.size() != 2) fail("write 'timestep fixed DT'");
    done(a);
    s.dt_fixed = num(a.words[1]);
    if (s.dt_fixed <= 0.0) fail("the time step must be positive");
    s.dt_scaled = 0;
  } else {
    fail("'" + a.words[0] + "' is not a time step mode" +
         suggest(a.words[0], {"auto", "scaled", "fixed"}));
  }
  model_.dt_dirty = true;
}

}  // namespace tessera
