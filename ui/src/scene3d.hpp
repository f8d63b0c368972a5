// 3D models in a Scene: a parallel or perspective projection along the view's azimuth and
// elevation (the window's camera), faces turned away from the eye dropped, the rest shaded by how
// squarely they face the line of sight (the camera's headlight), each point with its height
// towards the viewer, so that figures and the window hide what is behind by a depth buffer (the
// faces come in no particular order). Contacts and arrows are drawn as in 2D from a projected
// snapshot.
#pragma once

#include <functional>
#include <optional>

#include "tessera/ui/scene.hpp"

namespace tessera::ui {

// The window camera's view angle in perspective (degrees, VTK's default).
constexpr double kViewAngle = 30.0;

// The view's axes: right and up on the screen, and towards the viewer (the eye). In
// perspective the eye is `distance` from `focus` along `eye`, and points are drawn where the line
// to the eye crosses the plane through the focus (the same size there as in parallel).
struct ViewAxes {
  Vec3 right, up, eye;
  bool perspective = false;
  Vec3 focus = Vec3::Zero();
  double distance = 0;
  ViewAxes(double azimuth, double elevation);  // degrees; parallel
  // Perspective if the options ask for it and hold the camera (has_camera).
  explicit ViewAxes(const ViewOptions& o);
  Vec2 operator()(const Vec3& p) const;
  // The height towards the viewer as a depth buffer takes it: p.eye in parallel; in perspective
  // D h / (D - h), h the height above the focal plane (it grows with h, and varies linearly
  // across a drawn triangle, so that interpolated depths are exact).
  double depth(const Vec3& p) const;
  // Whether a point lies in front of the eye (beyond a near plane at a hundredth of the distance).
  bool in_front(const Vec3& p) const;
  // How squarely a plane through p of unit normal n faces the eye (the cosine; > 0: towards it).
  double facing(const Vec3& n, const Vec3& p) const;
};

// The window's camera fitted to points seen along (azimuth, elevation) in a viewport of this
// aspect (width / height): the focal point (their box's middle), the half height shown there
// in parallel (scale) and the eye's distance (far enough that a perspective view shows the same
// at the focal point and every point, and outside the points' sphere).
struct CameraFit {
  Vec3 focus = Vec3::Zero();
  double scale = 1, distance = 1;
};
CameraFit fit_camera(const std::vector<Vec3>& pts, double azimuth, double elevation, double aspect);
// The options with the perspective camera set (has_camera): as given, or fitted to the shown
// model as the window fits it in a 3:2 viewport. Unchanged unless perspective.
ViewOptions with_camera(const Snapshot& s, const ViewOptions& o);

// Points on a plane of normal n (the crossings of a convex polygon or polyhedron with it) as a
// polygon turned about n, each point once; empty if fewer than three remain.
std::vector<Vec3> polygon_about(const Vec3& n, std::vector<Vec3> pts);

// Whether a point is cut away by the view's cut (ViewOptions::cut): it lies above the plane.
bool cut_away(const ViewOptions& o, const Vec3& p);

// The snapshot with block centroids, displacements and sub-contacts projected onto the view
// plane (its 2D fields), for the contact bars and displacement arrows.
Snapshot flatten3(const Snapshot& s, const ViewOptions& o);
// A sub-contact's point as drawn: magnified like the blocks, moving with block a.
Vec3 shown_point3(const Snapshot& s, const ViewOptions& o, const SnapshotContact& c);
// A support point (node k of a cable) as drawn: magnified with the block that hosts it.
Vec3 shown_support3(const Snapshot& s, const ViewOptions& o, const SnapshotBolt& b, size_t k);
// The contact bars' heights towards the viewer (the sub-contacts' points, magnified like the
// blocks), for bars built from the projected snapshot.
void set_bar_depths3(const Snapshot& s, const ViewOptions& o, Scene& out);
// Block faces as polygons in view coordinates, coloured per block (for a camera, Scene::camera:
// every face, unshaded, with its world points). A cut clips the faces to the part below it and
// keeps the faces turned away, whose inside then shows through the opening. With `zone_colour`, the
// faces of deformable blocks are drawn as their surface triangles (on the magnified nodes), each
// in the colour of the zone it bounds; a zone given no colour (null) leaves its triangle out.
void add_faces3(const Snapshot& s, const ViewOptions& o, const std::vector<Rgb>& colours,
                Scene& out,
                const std::function<std::optional<Rgb>(const SnapshotZone&)>& zone_colour = {});

}  // namespace tessera::ui
