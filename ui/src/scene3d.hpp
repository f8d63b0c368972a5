// 3D models in a Scene: a parallel projection along the view's azimuth and elevation, faces
// turned away dropped, the rest shaded by how squarely they face the viewer, each point with its
// height towards the viewer, so that figures and the window hide what is behind by a depth
// buffer (the faces come in no particular order). Contacts and arrows are drawn as in 2D from a
// projected snapshot.
#pragma once

#include <functional>
#include <optional>

#include "tessera/ui/scene.hpp"

namespace tessera::ui {

// The view's axes: right and up on the screen, and towards the viewer (the eye).
struct ViewAxes {
  Vec3 right, up, eye;
  ViewAxes(double azimuth, double elevation);  // degrees
  explicit ViewAxes(const ViewOptions& o) : ViewAxes(o.azimuth, o.elevation) {}
  Vec2 operator()(const Vec3& p) const { return {p.dot(right), p.dot(up)}; }
};

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
