// The viewport's 3D half: a camera on the model's own coordinates, the triad, the cut plane and
// VTK's cell picker.
#include <vtkActor.h>
#include <vtkAxesActor.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkCellPicker.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkMapper.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "scene3d.hpp"
#include "tessera/ui/vtk_view.hpp"
#include "vtk_polydata.hpp"

namespace tessera::ui {

namespace {
void move_camera(vtkCamera* cam, const Vec3& shift) {
  double f[3], p[3];
  cam->GetFocalPoint(f), cam->GetPosition(p);
  cam->SetFocalPoint(f[0] + shift.x(), f[1] + shift.y(), f[2] + shift.z());
  cam->SetPosition(p[0] + shift.x(), p[1] + shift.y(), p[2] + shift.z());
}
}  // namespace

void VtkView::rebuild3() {
  std::vector<std::vector<Vec3>> faces, outlines;
  std::vector<Rgb> colours, outline_colours;
  std::vector<std::array<Vec3, 2>> highlight;
  face_block_.clear(), face_zone_.clear();
  for (const auto& p : scene_.polygons) {
    if (p.world.size() < 3) continue;
    faces.push_back(p.world), colours.push_back(p.colour), face_block_.push_back(p.block);
    face_zone_.push_back(p.zone);
    if (p.outline) outlines.push_back(p.world), outline_colours.push_back(p.colour);
    if (std::find(highlight_blocks_.begin(), highlight_blocks_.end(), p.block) !=
        highlight_blocks_.end())
      for (size_t k = 0; k < p.world.size(); ++k)
        highlight.push_back({p.world[k], p.world[(k + 1) % p.world.size()]});
  }
  in_place_ += fill_polygons(blocks_, faces, colours);
  fill_polygons(edges_, outlines, outline_colours);
  fill_lines(highlight_, highlight);
  fill_polygons(zones_, {}, {});
  faces.clear(), colours.clear();
  std::vector<std::array<Vec3, 2>> support;
  std::vector<Rgb> support_colours;
  for (const auto& b : scene_.bars)
    if (b.over)
      support.push_back({b.world[0], b.world[1]}), support_colours.push_back(b.colour);
    else
      faces.push_back({b.world[0], b.world[1], b.world[2], b.world[3]}),
          colours.push_back(b.colour);
  fill_polygons(bars_, faces, colours);
  fill_lines(support_, support, support_colours);
  // Arrows: shaft and two head strokes, in a plane holding the arrow.
  std::vector<std::array<Vec3, 2>> strokes;
  for (const auto& a : scene_.arrows) {
    const Vec3 d = a.head3 - a.tail3, n = d.norm() * d.unitOrthogonal();
    strokes.push_back({a.tail3, a.head3});
    strokes.push_back({a.head3, a.head3 - 0.25 * d + 0.12 * n});
    strokes.push_back({a.head3, a.head3 - 0.25 * d - 0.12 * n});
  }
  fill_lines(arrows_, strokes);
}

void VtkView::setPreview3(const std::vector<std::array<Vec3, 2>>& segments) {
  fill_lines(preview_, segments);
  preview_count_ = segments.size();
  update();
}

double VtkView::worldPerPixel() {
  vtkCamera* cam = renderer_->GetActiveCamera();
  const double h = std::max(1.0, height() * (kModelViewport[3] - kModelViewport[1]));
  const double half =
      cam->GetParallelProjection()
          ? cam->GetParallelScale()
          : cam->GetDistance() * std::tan(cam->GetViewAngle() * std::numbers::pi / 360);
  return 2 * half / h;
}

void VtkView::aimCamera() {
  vtkCamera* cam = renderer_->GetActiveCamera();
  const ViewAxes v = ViewAxes(azimuth_, elevation_);
  double f[3];
  cam->GetFocalPoint(f);
  const Vec3 at = Vec3(f[0], f[1], f[2]) + cam->GetDistance() * v.eye;
  cam->SetPosition(at.data());
  cam->SetViewUp(v.up.data());
  renderer_->ResetCameraClippingRange();
}

void VtkView::resetCamera3() {
  std::vector<Vec3> pts;
  for (const auto& p : scene_.polygons) pts.insert(pts.end(), p.world.begin(), p.world.end());
  const double w = width() * (kModelViewport[2] - kModelViewport[0]),
               h = height() * (kModelViewport[3] - kModelViewport[1]);
  const CameraFit fit = fit_camera(pts, azimuth_, elevation_, h > 0 ? w / h : 1.0);
  const ViewAxes v = ViewAxes(azimuth_, elevation_);
  vtkCamera* cam = renderer_->GetActiveCamera();
  cam->SetViewAngle(kViewAngle);
  cam->SetParallelScale(fit.scale);
  cam->SetFocalPoint(fit.focus.data());
  const Vec3 eye = fit.focus + fit.distance * v.eye;
  cam->SetPosition(eye.data());
  cam->SetViewUp(v.up.data());
  cam->SetParallelProjection(!perspective_);
  renderer_->ResetCameraClippingRange();
  update();
}

void VtkView::pan3(QPoint from, QPoint to) {
  const ViewAxes v = ViewAxes(azimuth_, elevation_);
  const QPoint d = to - from;
  move_camera(renderer_->GetActiveCamera(), worldPerPixel() * (-d.x() * v.right + d.y() * v.up));
  renderer_->ResetCameraClippingRange();
}

void VtkView::zoom3(QPoint at, double factor) {
  vtkCamera* cam = renderer_->GetActiveCamera();
  const ViewAxes v = ViewAxes(azimuth_, elevation_);
  // The cursor's offset from the viewport's centre: the model point there stays put.
  const double cx = width() * 0.5 * (kModelViewport[0] + kModelViewport[2]),
               cy = height() * (1 - 0.5 * (kModelViewport[1] + kModelViewport[3]));
  const Vec3 offset = (at.x() - cx) * v.right - (at.y() - cy) * v.up;
  const double before = worldPerPixel();
  if (cam->GetParallelProjection())
    cam->SetParallelScale(cam->GetParallelScale() * factor);
  else
    cam->Dolly(1.0 / factor);
  move_camera(cam, (before - worldPerPixel()) * offset);
  renderer_->ResetCameraClippingRange();
}

void VtkView::placeTriad() {
  const bool shown = has_scene_ && scene_.three;
  triad_->SetDraw(shown);
  if (!shown) return;
  vtkCamera* cam = renderer_->GetActiveCamera();
  vtkCamera* t = triad_->GetActiveCamera();
  double dop[3];
  cam->GetDirectionOfProjection(dop);
  // Looking at the triad's middle from the model camera's direction, the unit axes filling the
  // corner whatever the labels' extent.
  t->SetFocalPoint(0.5, 0.5, 0.5);
  t->SetPosition(0.5 - 5 * dop[0], 0.5 - 5 * dop[1], 0.5 - 5 * dop[2]);
  t->SetViewUp(cam->GetViewUp());
  t->ParallelProjectionOn();
  t->SetParallelScale(0.95);
  triad_->ResetCameraClippingRange(-2, 2, -2, 2, -2, 2);
}

void VtkView::pick3(QPoint at) {
  const double r = devicePixelRatioF();
  int block = -1, contact = -1, zone = -1;
  if (picker_->Pick(at.x() * r, (height() - at.y()) * r, 0, renderer_) &&
      picker_->GetCellId() >= 0 && picker_->GetDataSet()) {
    vtkDataArray* index = picker_->GetDataSet()->GetCellData()->GetArray("index");
    const int i = index ? static_cast<int>(index->GetTuple1(picker_->GetCellId())) : -1;
    if (i >= 0 && picker_->GetActor() == bars_actor_.Get() &&
        static_cast<size_t>(i) < scene_.bars.size())
      contact = scene_.bars[static_cast<size_t>(i)].contact;
    else if (i >= 0 && picker_->GetActor() == blocks_actor_.Get() &&
             static_cast<size_t>(i) < face_block_.size())
      block = face_block_[static_cast<size_t>(i)], zone = face_zone_[static_cast<size_t>(i)];
  }
  emit picked(block, contact);
  if (zone >= 0) emit zonePicked(zone);
}

QVector<int> VtkView::blocksIn(const QRect& r) {
  std::vector<Vec3> sum;
  std::vector<int> count;
  for (const auto& p : scene_.polygons) {
    if (p.block < 0) continue;
    const auto b = static_cast<size_t>(p.block);
    if (b >= sum.size()) sum.resize(b + 1, Vec3::Zero()), count.resize(b + 1, 0);
    for (const Vec3& v : p.world) sum[b] += v, ++count[b];
  }
  const double ratio = devicePixelRatioF();
  QVector<int> inside;
  for (size_t b = 0; b < sum.size(); ++b) {
    if (!count[b]) continue;
    const Vec3 c = sum[b] / count[b];
    renderer_->SetWorldPoint(c.x(), c.y(), c.z(), 1);
    renderer_->WorldToDisplay();
    const double* d = renderer_->GetDisplayPoint();
    if (r.contains(
            QPoint(static_cast<int>(d[0] / ratio), static_cast<int>(height() - d[1] / ratio))))
      inside.append(static_cast<int>(b));
  }
  return inside;
}

void VtkView::visibleWindow3(Vec2& lo, Vec2& hi) {
  // The camera's window in the figures' view coordinates (right and up of the same view).
  double f[3];
  renderer_->GetActiveCamera()->GetFocalPoint(f);
  const Vec2 centre = ViewAxes(azimuth_, elevation_)(Vec3(f[0], f[1], f[2]));
  const double wpp = worldPerPixel();
  const Vec2 half(0.5 * wpp * width() * (kModelViewport[2] - kModelViewport[0]),
                  0.5 * wpp * height() * (kModelViewport[3] - kModelViewport[1]));
  lo = centre - half, hi = centre + half;
}

void VtkView::setPerspective(bool on) {
  perspective_ = on;
  vtkCamera* cam = renderer_->GetActiveCamera();
  // 2D views stay parallel; a 3D view takes the setting when it is shown.
  if (!scene_.three || on == !cam->GetParallelProjection()) return;
  // The same size at the focal point either way.
  const double tangent = std::tan(cam->GetViewAngle() * std::numbers::pi / 360);
  if (on) {
    cam->SetDistance(std::max(cam->GetParallelScale() / tangent, 1e-9));
  } else {
    cam->SetParallelScale(cam->GetDistance() * tangent);
  }
  cam->SetParallelProjection(!on);
  renderer_->ResetCameraClippingRange();
  update();
}

bool VtkView::perspective() const {
  return perspective_;
}

void VtkView::camera3(Vec3& focus, double& distance) {
  vtkCamera* cam = renderer_->GetActiveCamera();
  double f[3];
  cam->GetFocalPoint(f);
  focus = Vec3(f[0], f[1], f[2]), distance = cam->GetDistance();
}

void VtkView::setSeeThrough(bool on) {
  see_through_ = on;
  blocks_actor_->GetProperty()->SetOpacity(scene_.three && on ? 0.25 : 1.0);
  update();
}

bool VtkView::seeThrough() const {
  return see_through_;
}

}  // namespace tessera::ui
