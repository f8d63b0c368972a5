// What a picture of a snapshot holds, in model coordinates: coloured block polygons, contact
// bars, displacement arrows and the legends that explain them.
//
// The VTK view and the figure writer both draw a Scene, so the window, a PNG and a PDF of the
// same model and options show the same colours, widths and legends.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tessera/io/figure.hpp"
#include "tessera/ui/colour_map.hpp"
#include "tessera/ui/snapshot.hpp"

namespace tessera::ui {

struct ScenePolygon {
  std::vector<Vec2> points;
  Rgb colour;
  int block = -1;             // index in the snapshot
  int zone = -1;              // the zone it draws (zones coloured by value), else -1
  bool outline = true;        // drawn with a dark edge (a 3D zone's surface triangle is not)
  std::vector<double> depth;  // 3D: each point's height towards the viewer, for a depth buffer
  std::vector<Vec3> world;    // 3D: the points in model coordinates (magnified), for a camera
};

// A contact drawn as a bar along the joint, its width showing the normal force.
struct SceneBar {
  Vec2 corners[4];
  Rgb colour;
  int contact = -1;
  double depth = 0;  // 3D: the sub-contact's height towards the viewer
  Vec3 world[4] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};  // 3D, for a camera:
  // a square in the sub-contact's plane
  // A bolt's or cable's segment (contact -1): its index in Snapshot::bolts and the segment. In 3D
  // support lies inside the rock, so it is drawn over the faces (`over`), with the segment's ends
  // in model coordinates (world[0], world[1]) for a camera.
  int support = -1, segment = -1;
  bool over = false;
};

struct SceneArrow {
  Vec2 tail, head;
  Vec3 tail3 = Vec3::Zero(), head3 = Vec3::Zero();  // 3D: in model coordinates
};

// A continuous colour bar (range, units) or a list of named colours.
struct Legend {
  std::string title;
  bool continuous = false;
  double lo = 0, hi = 0;
  // A continuous range clipped to percentiles (so that one spike does not wash out the rest):
  // the values' true extremes.
  bool clipped = false;
  double min = 0, max = 0;
  std::vector<std::pair<std::string, Rgb>> entries;
};

struct Scene {
  std::vector<ScenePolygon> polygons;  // blocks: filled, then outlined over the zones
  std::vector<ScenePolygon> zones;     // zones of deformable blocks, when coloured by zone
  std::vector<SceneBar> bars;
  std::vector<SceneArrow> arrows;
  Legend blocks_legend, contacts_legend;
  Legend support_legend;                      // bolts' states (2D), in figures below the others
  std::string title, caption;                 // caption: cycle, time, force scale
  Vec2 lo = Vec2::Zero(), hi = Vec2::Zero();  // what to show
  double arrow_scale = 0;                     // drawn length per metre of displacement
  std::vector<uint8_t> deformable_blocks;     // by snapshot block index
  bool three = false;  // a 3D model, drawn in view coordinates (with depths: no hand sorting)
  // A 3D scene for a camera (the window): every face, turned away or not, in its own colour
  // (the camera's light shades it), with world points; figures are drawn in view coordinates.
  bool camera = false;
  double azimuth = 0, elevation = 0;  // 3D: the view it was built for (degrees)
  // 3D: projected in perspective (figures draw no scale bar: lengths vary with depth).
  bool perspective = false;
  bool deformable(int block) const {
    return block >= 0 && static_cast<size_t>(block) < deformable_blocks.size() &&
           deformable_blocks[static_cast<size_t>(block)];
  }
};

// `camera`: a 3D model for the window's camera (Scene::camera); figures leave it off.
Scene build_scene(const Snapshot& s, const ViewOptions& o, bool camera = false);

// The block value a colour option shows, and its legend title with units.
double block_value(const SnapshotBlock& b, ColourBy c);
// The zone value a colour option shows (stresses in MPa), and the state category of zone bits:
// 0 elastic, 1 yielding in shear now, 2 in tension now, 3 yielded before.
double zone_value(const SnapshotZone& z, ColourBy c);
int zone_state_category(uint8_t state);
std::string value_title(ColourBy c);
// Index of the block under a model point (-1 if none) and of the contact bar (-1).
int block_at(const Scene& scene, Vec2 p);
int bar_at(const Scene& scene, Vec2 p);
// Index of the zone drawn under a model point (2D scenes with zones coloured; -1 if none).
int zone_at(const Scene& scene, Vec2 p);

}  // namespace tessera::ui
