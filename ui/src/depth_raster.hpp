// A depth-buffered picture of a 3D scene for figures: each pixel shows the nearest face, so a
// face behind another contributes nothing wherever it is hidden, whatever the faces' sizes
// (sorting whole faces by depth, the painter's order, is not exact: a footing's large top face
// was painted over the bricks standing on it). Block outlines and contact bars are depth-tested
// too, a hair in front of their faces: a sub-contact behind a block is not drawn.
#pragma once

#include <QImage>
#include <QPointF>
#include <functional>

#include "tessera/ui/scene.hpp"

namespace tessera::ui {

// The faces (with outlines `edge_px` wide) and contact bars of a 3D scene in an image of `size`
// pixels, transparent where nothing is; `map` takes view coordinates to the image's pixels.
QImage depth_raster(const Scene& s, QSize size, const std::function<QPointF(const Vec2&)>& map,
                    double edge_px);

}  // namespace tessera::ui
