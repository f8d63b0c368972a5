// Scene pieces as VTK polydata, shared by the 2D and 3D halves of the viewport.
#pragma once

#include <array>
#include <vector>

#include "tessera/ui/scene.hpp"

class vtkPolyData;

namespace tessera::ui {

// Filled polygons with one RGB colour ("colour") and their index in the list ("index", which a
// picked cell carries through VTK's triangle filter) per cell. When the polydata already holds
// polygons of the same sizes (a run's next frame), its points and colours are updated in place
// and true is returned.
bool fill_polygons(vtkPolyData* pd, const std::vector<std::vector<Vec3>>& polys,
                   const std::vector<Rgb>& colours);
// Line segments as line cells, with an RGB colour per cell if colours are given.
void fill_lines(vtkPolyData* pd, const std::vector<std::array<Vec3, 2>>& segments,
                const std::vector<Rgb>& colours = {});

}  // namespace tessera::ui
