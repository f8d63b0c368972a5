// 3D models in a Scene: a parallel projection along the view's azimuth and elevation, faces
// turned away dropped, the rest shaded by how squarely they face the viewer and drawn from the
// farthest (painter's order). Contacts and arrows are drawn as in 2D from a projected snapshot.
#pragma once

#include <functional>
#include <optional>

#include "tessera/ui/scene.hpp"

namespace tessera::ui {

// The snapshot with block centroids, displacements and sub-contacts projected onto the view
// plane (its 2D fields), for the contact bars and displacement arrows.
Snapshot flatten3(const Snapshot& s, const ViewOptions& o);
// Block faces as polygons in view coordinates, coloured per block. With `zone_colour`, the
// faces of deformable blocks are drawn as their surface triangles (on the magnified nodes), each
// in the colour of the zone it bounds; a zone given no colour (null) leaves its triangle out.
void add_faces3(const Snapshot& s, const ViewOptions& o, const std::vector<Rgb>& colours,
                Scene& out,
                const std::function<std::optional<Rgb>(const SnapshotZone&)>& zone_colour = {});

}  // namespace tessera::ui
