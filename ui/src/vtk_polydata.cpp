#include "vtk_polydata.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkIntArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

namespace tessera::ui {

void fill_lines(vtkPolyData* pd, const std::vector<std::array<Vec3, 2>>& segments,
                const std::vector<Rgb>& colours) {
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetNumberOfComponents(3);
  rgb->SetName("colour");
  for (size_t i = 0; i < segments.size(); ++i) {
    const auto& s = segments[i];
    const vtkIdType ids[2] = {pts->InsertNextPoint(s[0].data()), pts->InsertNextPoint(s[1].data())};
    lines->InsertNextCell(2, ids);
    if (i < colours.size()) {
      const unsigned char c[3] = {colours[i].r, colours[i].g, colours[i].b};
      rgb->InsertNextTypedTuple(c);
    }
  }
  pd->Initialize();
  pd->SetPoints(pts);
  pd->SetLines(lines);
  if (!colours.empty()) pd->GetCellData()->SetScalars(rgb);
}

namespace {
// Whether the polydata holds polygons of these sizes, in this order (a run's next frame).
bool same_cells(vtkPolyData* pd, const std::vector<std::vector<Vec3>>& polys) {
  vtkCellArray* cells = pd->GetPolys();
  if (!cells || !pd->GetPoints() || cells->GetNumberOfCells() != vtkIdType(polys.size()))
    return false;
  vtkIdType total = 0;
  for (size_t i = 0; i < polys.size(); ++i) {
    if (cells->GetCellSize(vtkIdType(i)) != vtkIdType(polys[i].size())) return false;
    total += vtkIdType(polys[i].size());
  }
  return pd->GetNumberOfPoints() == total &&
         vtkUnsignedCharArray::SafeDownCast(pd->GetCellData()->GetScalars());
}
}  // namespace

bool fill_polygons(vtkPolyData* pd, const std::vector<std::vector<Vec3>>& polys,
                   const std::vector<Rgb>& colours) {
  if (same_cells(pd, polys)) {
    // The same polygons moved or recoloured: the arrays VTK holds are updated in place.
    vtkPoints* points = pd->GetPoints();
    auto* rgb = vtkUnsignedCharArray::SafeDownCast(pd->GetCellData()->GetScalars());
    vtkIdType k = 0;
    for (size_t i = 0; i < polys.size(); ++i) {
      for (const Vec3& p : polys[i]) points->SetPoint(k++, p.data());
      const unsigned char c[3] = {colours[i].r, colours[i].g, colours[i].b};
      rgb->SetTypedTuple(vtkIdType(i), c);
    }
    points->Modified(), rgb->Modified(), pd->Modified();
    return true;
  }
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetNumberOfComponents(3);
  rgb->SetName("colour");
  vtkNew<vtkIntArray> index;
  index->SetName("index");
  for (size_t i = 0; i < polys.size(); ++i) {
    cells->InsertNextCell(static_cast<int>(polys[i].size()));
    for (const Vec3& p : polys[i]) cells->InsertCellPoint(points->InsertNextPoint(p.data()));
    const unsigned char c[3] = {colours[i].r, colours[i].g, colours[i].b};
    rgb->InsertNextTypedTuple(c);
    index->InsertNextValue(static_cast<int>(i));
  }
  pd->Initialize();
  pd->SetPoints(points);
  pd->SetPolys(cells);
  pd->GetCellData()->SetScalars(rgb);
  pd->GetCellData()->AddArray(index);
  return false;
}

}  // namespace tessera::ui
