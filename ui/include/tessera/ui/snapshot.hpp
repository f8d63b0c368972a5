// A copy of what the window shows of a model, taken on the solver's thread between cycles.
//
// The view never reads the live model: the worker copies positions, contact forces and the
// model's catalogue (groups, materials, joints, histories, stages) into a Snapshot and hands it
// over whole, so drawing can take its time while the solver cycles on.
#pragma once

#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include "tessera/contact3d/polyhedron.hpp"
#include "tessera/core/geometry.hpp"

namespace tessera {
struct Model;
struct StageRecord;
}  // namespace tessera

namespace tessera::ui {

struct SnapshotBlock {
  int id = 0, group = -1, material = -1;
  double x = 0, y = 0, x_ref = 0, y_ref = 0, theta = 0;
  double vx = 0, vy = 0, omega = 0;
  double z = 0, z_ref = 0, vz = 0;  // 3D models (theta: the angle turned, omega: its rate)
  double area = 0, mass = 0;        // 3D models: volume (m³) and mass (kg)
  uint8_t fixity = 0;
  bool deformable = false;  // then local holds outline node positions, start their originals
  uint32_t vert_begin = 0, vert_end = 0;  // into Snapshot::local
};

struct SnapshotContact {
  int a = 0, b = 0;  // block indices
  Vec2 point = Vec2::Zero(), normal = Vec2::Zero();
  // The stretch of joint the contact stands for (contact_stretches: its share of its joint
  // line, §5.2.2's L = RQ1/2 + RQ2/2, where the joint runs; its length about its point alone).
  Vec2 from = Vec2::Zero(), to = Vec2::Zero();
  // 3D models: a sub-contact's point and the common plane's normal (length: half the side of
  // a square of its area; forces in N).
  Vec3 point3 = Vec3::Zero(), normal3 = Vec3::Zero();
  double length = 0, gap = 0, fn = 0, fs = 0, shear_disp = 0;
  uint8_t flags = 0;
  std::string joint;      // joint property name
  std::string joint_set;  // name of the joint set, crack or opening it lies on (may be empty)
};

// A zone of a deformable block: its nodes (into Snapshot::nodes), block, stress, plastic state.
// In 3D models every zone is kept, for the stress of its surface triangles (tris3); a null
// (excavated) zone has block -1.
struct SnapshotZone {
  uint32_t n[4] = {0, 0, 0, 0};  // corner nodes: a triangle's three, a tetrahedron's four
  uint32_t index = 0;            // the model's zone number less one (null zones are left out)
  int block = -1;
  double sxx = 0, syy = 0, sxy = 0, szz = 0;
  double syz = 0, sxz = 0;  // 3D
  uint8_t state = 0;
};

// A bolt (2D): its ends and crossings in order, each with the block it is fixed in (for a
// magnified shape) and the element's forces and state (zero at the ends). A cable: its nodes,
// their hosts, the axial force of the segment from each node to the next, and kBoltAxialYield
// where that segment yields or the node's grout slips.
struct SnapshotBolt {
  std::string name;
  bool cable = false;
  bool liner = false;   // a liner, drawn as a cable is (its axial force: tension positive)
  bool closed = false;  // a liner ring: its last point is its first node again
  std::vector<Vec2> points;
  std::vector<Vec3> points3;  // 3D models' cables (points: x and y)
  std::vector<int> block;
  std::vector<double> axial, shear;
  std::vector<uint8_t> state;  // BoltState bits; a liner's node also kLinerNodeOpen
};
// A liner node open from the rock (its interface in tension, at no capacity): drawn elastic.
constexpr uint8_t kLinerNodeOpen = 0x80;

// A named list of properties, for the model tree and property panel.
struct Entry {
  std::string name;
  std::vector<std::pair<std::string, std::string>> properties;
};

struct Snapshot {
  uint64_t serial = 0;  // increases with every snapshot the worker takes
  // Made on this thread (the solver's); `held`: taken by a pause, the solver waits after it.
  std::thread::id made_on;
  bool held = false;
  std::string title;
  uint64_t cycle = 0;
  double time = 0, dt = 0, ratio = 1;
  double rounding = 0;  // the corner rounding length (0: not set yet)
  std::vector<SnapshotBlock> blocks;
  std::vector<Vec2> local;  // block vertices relative to the centroid, unrotated
  std::vector<Vec2> start;  // deformable blocks: where each outline node started
  std::vector<SnapshotContact> contacts;
  std::vector<SnapshotBolt> bolts;
  // Zones of deformable blocks, and their nodes as they are and as they started.
  std::vector<SnapshotZone> zones;
  std::vector<Vec2> nodes, nodes_start;
  std::vector<std::string> groups;
  std::vector<std::string> joint_names;  // joint sets, cracks and openings, by tag
  std::vector<Entry> materials, joints, conditions, stages;
  // Histories, thinned to at most kHistoryRows rows spread over the whole run.
  static constexpr size_t kHistoryRows = 2000;
  std::vector<std::string> history_labels;
  std::vector<std::string> history_titles;  // what each is, with its unit: "ydisp [m]"
  std::vector<double> history_cycles;
  std::vector<std::vector<double>> history_values;  // one vector per series
  // Corners of the box around the blocks.
  Vec2 lo = Vec2::Zero(), hi = Vec2::Zero();
  // 3D models: every block face as a polygon of world points (blocks keep no 2D outline).
  bool three = false;
  struct Face3 {
    int block = -1;
    uint32_t begin = 0, end = 0;  // into points3
  };
  std::vector<Vec3> points3;
  std::vector<Face3> faces3;
  // 3D deformable blocks: each surface triangle of a face (nodes into nodes3, its face in
  // faces3, the zone it bounds in zones), and the nodes as they are and as they started.
  struct Tri3 {
    uint32_t n[3] = {0, 0, 0};
    uint32_t face = 0, zone = 0;
  };
  std::vector<Tri3> tris3;
  std::vector<Vec3> nodes3, nodes3_start;
};

// Takes a snapshot of the model (block world caches must be current).
Snapshot make_snapshot(const Model& m, const std::string& title,
                       const std::vector<StageRecord>& stages);

// A block's vertex with the displacement and rotation since creation multiplied by `magnify`.
Vec2 shown_vertex(const Snapshot& s, const SnapshotBlock& b, uint32_t v, double magnify);

}  // namespace tessera::ui
