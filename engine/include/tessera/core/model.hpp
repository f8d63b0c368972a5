// The whole state of a model, 2D or 3D: blocks, contacts, properties, settings, clock.
//
// Everything needed to continue a run bit for bit lives here and is written by save(), except
// the run options; the cycle (step.hpp) is a set of free functions over this state.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "tessera/contact2d/blocks.hpp"
#include "tessera/contact2d/contacts.hpp"
#include "tessera/contact3d/blocks3.hpp"
#include "tessera/contact3d/contacts3.hpp"
#include "tessera/core/history.hpp"
#include "tessera/core/joint_law.hpp"
#include "tessera/core/run_options.hpp"
#include "tessera/support/cables.hpp"
#include "tessera/support/liners.hpp"
#include "tessera/support/reinforcement.hpp"
#include "tessera/zones/continuum.hpp"

namespace tessera {

struct Material {
  std::string name;
  double density = 0.0;  // kg/m^3
  // What zones of this material are (for deformable blocks); zone.model is empty if the
  // material has no elastic constants.
  ZoneProperties zone;
};

// kKinetic: local damping (kinetic_alpha) and every velocity set to zero whenever the kinetic
// energy has passed a peak (kinetic damping of dynamic relaxation), for static solutions.
enum class DampingMode : uint8_t { kLocal = 0, kAdaptiveGlobal = 1, kNone = 2, kKinetic = 3 };

struct Settings {
  Vec2 gravity = Vec2::Zero();
  Vec3 gravity3 = Vec3::Zero();    // 3D models
  double rounding = 0.0;           // corner rounding length d
  double contact_tolerance = 0.0;  // contacts are tracked within this gap; 0: the rounding length
  DampingMode damping = DampingMode::kLocal;
  double local_alpha = 0.8;
  double global_ratio = 0.5;   // adaptive global damping: share of kinetic energy change removed
  double kinetic_alpha = 0.2;  // kinetic damping: the local damping beside the energy peaks
  double dt_safety = 0.5;      // time step = safety * 2 min sqrt(m/k)
  double dt_fixed = 0.0;       // a user's time step (0: automatic)
  // Density scaling of deformable blocks for static solutions: the step is the median of the
  // nodes' own stable steps, and nodes below it take more inertia (gravity keeps the real mass).
  uint8_t dt_scaled = 0;
};

// Joint property set used for contacts between two groups (-1 matches any group) along joints
// of one tag (a joint set, crack or opening; -1 matches any).
struct JointAssignment {
  int group_a = -1, group_b = -1;
  uint32_t joint = 0;
  int tag = -1;
};

struct Model {
  // 2 or 3: which block store the model uses (the other stays empty). Materials, joints,
  // groups, histories, the clock and the settings serve both.
  uint8_t dim = 2;
  Settings settings;
  Blocks blocks;
  Contacts contacts;
  Blocks3 blocks3;
  std::vector<Contact3> contacts3;
  // Set by each cycle's 3D law for its integration: whether contact i re-fits its plane or
  // rebuilds its sub-contacts next cycle, reading its blocks' vertices (one byte a contact, so
  // that each block's question reads a few bytes, not a contact record each).
  std::vector<uint8_t> reads_vertices3;
  std::vector<Material> materials;
  std::vector<JointProperties> joints;
  std::vector<JointAssignment> joint_table;  // later entries win
  std::vector<std::string> groups;
  std::vector<std::string> joint_tags;  // names of joint sets, cracks and openings
  Histories histories;
  // Nodes and zones of the deformable blocks. Zone material k + 1 is model material k; zone
  // material 0 is null (excavated).
  Continuum continuum;
  // The same for deformable 3D blocks (tetrahedra); the blocks' surfaces are in Blocks3.
  Continuum3 continuum3;
  // Rock support: bolts across joints (2D).
  Reinforcement support;
  // Grouted cables (2D and 3D) and liners (2D).
  Cables cables;
  Cables3 cables3;
  Liners liners;

  // Clock.
  uint64_t cycle = 0;
  double time = 0.0, dt = 0.0;
  bool dt_dirty = true;
  // Density scaling of the rigid blocks (`timestep scaled`): each block's mass and moments of
  // inertia in its motion are multiplied by these (translation, rotation); gravity and reported
  // masses keep the real density. Empty when the model is not scaled.
  std::vector<std::array<double, 2>> block_scale;
  // Adaptive global damping coefficient (1/s).
  double global_c = 0.0;
  // Kinetic damping: twice the kinetic energy after the last cycle (0 after a stop).
  double kinetic_last = 0.0;
  // Last cycle's convergence measures.
  double max_unbalanced = 0.0, mean_applied = 0.0, ratio = 1.0;
  // Block positions at the last detection pass (Verlet list), and whether one is due.
  std::vector<double> det_x, det_y, det_theta;
  std::vector<Vec2> det_node;
  std::vector<Vec3> det_node3;
  std::vector<Vec3> det_pos3;
  std::vector<Eigen::Quaterniond> det_q3;
  bool detection_due = true;
  uint64_t detection_passes = 0;
  // Contacts that detection dropped while they carried load through joint dilation (the joint
  // opened beyond the contact tolerance), and the largest such dilation: for a warning.
  uint64_t lost_dilated = 0;
  double lost_dilation = 0.0;
  void note_lost(uint8_t flags, double fn, double dilation) {
    if (!(flags & kTouching) || !(fn > 0.0) || !(dilation > 0.0)) return;
    ++lost_dilated, lost_dilation = std::max(lost_dilation, dilation);
  }

  // How this model runs (validation, profile): not saved, copied with the model.
  RunOptions options = default_run_options();

  // Derived, rebuilt after detection and after restore: the interfaces of each block, as
  // (index * 2 + side) with side 0 for a, 1 for b: in 3D a contact (one per pair of blocks), in
  // 2D a pair of blocks (Contacts::pair_begin; its sides those of its first contact).
  std::vector<uint32_t> block_contact_begin, block_contacts;

  // Group index by name; creates it when asked.
  int group_index(const std::string& name, bool create);
  int material_index(const std::string& name) const;
  int joint_index(const std::string& name) const;
  // Joint property set for a contact between two blocks along a joint of a tag, or -1.
  int joint_for(uint32_t a, uint32_t b, int tag = -1) const;
  size_t block_count() const { return dim == 3 ? blocks3.size() : blocks.size(); }
  int block_group(size_t b) const { return dim == 3 ? blocks3.group[b] : blocks.group[b]; }
  // "block 12 (group rock)", for messages ("(group (none))" without one).
  std::string block_label(size_t b) const;
  // Contact tolerance in force: the user's, or the rounding length.
  double tolerance() const {
    return settings.contact_tolerance > 0.0 ? settings.contact_tolerance : settings.rounding;
  }
  // Gaps this close to zero are round-off of the coordinates, not openings (see joint_law.hpp).
  double roundoff_gap() const { return 1e-9 * tolerance(); }
  // Contacts found at assembly this close (or closer) are shut joints and may be bonded.
  double bond_gap() const { return 1e-3 * tolerance(); }
  // Marks geometry or properties changed: time step and contacts are refreshed before cycling.
  void touch() { dt_dirty = true, detection_due = true; }
  // Rebuilds the per-block interface lists from each interface's two blocks (2D or 3D).
  void build_block_contacts();
  // What is wrong with the per-block contact lists, or empty if they match the contacts.
  std::string block_contacts_problem() const;
  // Roughly the memory the model takes (its large arrays, 2D and 3D), in bytes.
  double approx_bytes() const;
};

}  // namespace tessera
