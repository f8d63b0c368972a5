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
// stress, or by joint shear displacement. Widths always scale with the normal stress: each bar
// spans the stretch of joint its contact stands for, so its area is the force, however the
// joint's length is shared among its contacts (two corners meeting at one point share it).
enum class ContactShow : int { kOff, kState, kStress, kShear };

const std::vector<std::string>& colour_by_names();
const std::vector<std::string>& contact_show_names();
// Parses a name; false if unknown.
bool parse_colour_by(const std::string& word, ColourBy& c);
bool parse_contact_show(const std::string& word, ContactShow& c);

// What to draw, shared by the view and figures.
struct ViewOptions {
  ColourBy colour = ColourBy::kGroup;
  ContactShow contacts = ContactShow::kState;
  bool vectors = false;        // displacement vectors at block centroids
  double magnify = 1.0;        // deformed shape: displacements times this
  bool support_force = false;  // bolts and cables coloured by axial force, else by state
  bool has_window = false;     // a window in model coordinates, else the whole model
  Vec2 lo = Vec2::Zero(), hi = Vec2::Zero();
  std::string title;
  // 3D models: where the view looks from - azimuth clockwise from north (+y) and elevation
  // above the horizon, in degrees. The window is then in view coordinates (in perspective, on
  // the plane through the focal point across the line of sight).
  double azimuth = 210.0, elevation = 25.0;
  // 3D models: a perspective view (the window's camera: a 30 degree view angle) rather than a
  // parallel one. The eye is `distance` from `focus` towards the viewer when `has_camera` (a
  // figure of the window's camera), else fitted to the model as the window fits it.
  bool perspective = false;
  bool has_camera = false;
  Eigen::Vector3d focus = Eigen::Vector3d::Zero();
  double distance = 0.0;
  // 3D models: a cut to look inside - what lies above the plane (on the side its upward normal
  // points to; for a vertical plane, towards its dip direction) is not drawn.
  bool cut = false;
  double cut_dip = 90.0, cut_dip_direction = 0.0;  // degrees, dip direction clockwise from north
  Eigen::Vector3d cut_point = Eigen::Vector3d::Zero();
};

// The `figure` keyword perspective=on|off for a model of `dim` dimensions: sets it, or returns
// why not (not on or off; a 2D model, refused as view= and cut= are), else an empty string.
std::string set_perspective(ViewOptions& v, const std::string& word, int dim);

// One figure to write: PNG (pixels), SVG or PDF (the same size in points), by the extension.
struct FigureRequest {
  std::string path;
  int width = 1600, height = 1000;
  ViewOptions view;
};

using FigureSink = std::function<void(const FigureRequest&, const Model&)>;

}  // namespace tessera
