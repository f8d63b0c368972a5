// What a figure of the model shows: the request a script's `figure` command makes and the GUI's
// view options share this vocabulary, so a headless run draws what the window draws.
//
// The engine only parses and checks the request; drawing is the application's (ui/), handed in
// through a FigureSink, because the engine links neither Qt nor VTK.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "tessera/core/geometry.hpp"

namespace tessera {

struct Model;

// What the blocks are coloured by.
enum class ColourBy : int {
  kGroup,
  kMaterial,
  kDisplacement,
  kXDisp,
  kYDisp,
  kZDisp,  // 3D models (zero in 2D)
  kVelocity,
  kRotation,
  // Zones of deformable blocks (rigid blocks grey): stresses (tension positive), plastic state.
  kSxx,
  kSyy,
  kSxy,
  kSzz,
  kSigma1,
  kSigma3,
  kZoneState
};
// Whether an option colours zones rather than whole blocks.
inline bool colours_zones(ColourBy c) {
  return c >= ColourBy::kSxx;
}
// How contacts are drawn: not at all, coloured by state (open, slipping, elastic), by normal
// force, or by joint shear displacement. Widths always scale with normal force.
enum class ContactShow : int { kOff, kState, kForce, kShear };

const std::vector<std::string>& colour_by_names();
const std::vector<std::string>& contact_show_names();
// Parses a name; false if unknown.
bool parse_colour_by(const std::string& word, ColourBy& c);
bool parse_contact_show(const std::string& word, ContactShow& c);

// What to draw, shared by the view and figures.
struct ViewOptions {
  ColourBy colour = ColourBy::kGroup;
  ContactShow contacts = ContactShow::kState;
  bool vectors = false;     // displacement vectors at block centroids
  double magnify = 1.0;     // deformed shape: displacements times this
  bool has_window = false;  // a window in model coordinates, else the whole model
  Vec2 lo = Vec2::Zero(), hi = Vec2::Zero();
  std::string title;
  // 3D models: where the (parallel) view looks from - azimuth clockwise from north (+y) and
  // elevation above the horizon, in degrees. The window is then in view coordinates.
  double azimuth = 210.0, elevation = 25.0;
  // 3D models: a cut to look inside - what lies above the plane (on the side its upward normal
  // points to; for a vertical plane, towards its dip direction) is not drawn.
  bool cut = false;
  double cut_dip = 90.0, cut_dip_direction = 0.0;  // degrees, dip direction clockwise from north
  Eigen::Vector3d cut_point = Eigen::Vector3d::Zero();
};

// One figure to write: PNG (pixels), SVG or PDF (the same size in points), by the extension.
struct FigureRequest {
  std::string path;
  int width = 1600, height = 1000;
  ViewOptions view;
};

using FigureSink = std::function<void(const FigureRequest&, const Model&)>;

}  // namespace tessera
