// VTK pipeline and camera handling of the viewport.
#include "tessera/ui/vtk_view.hpp"

#include <vtkActor.h>
#include <vtkAxesActor.h>
#include <vtkAxisActor2D.h>
#include <vtkCamera.h>
#include <vtkCaptionActor2D.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellPicker.h>
#include <vtkDoubleArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkIntArray.h>
#include <vtkLookupTable.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTriangleFilter.h>
#include <vtkUnsignedCharArray.h>

#include <QKeyEvent>
#include <QMouseEvent>
#include <QRubberBand>
#include <QSurfaceFormat>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

#include "vtk_polydata.hpp"

namespace tessera::ui {

namespace {
// 2D polygons at height z.
std::vector<std::vector<Vec3>> at_height(const std::vector<std::vector<Vec2>>& polys, double z) {
  std::vector<std::vector<Vec3>> out(polys.size());
  for (size_t i = 0; i < polys.size(); ++i)
    for (const Vec2& p : polys[i]) out[i].emplace_back(p.x(), p.y(), z);
  return out;
}

// 2D line segments just above the model.
void fill_segments(vtkPolyData* pd, const std::vector<std::array<Vec2, 2>>& segments) {
  std::vector<std::array<Vec3, 2>> lifted;
  for (const auto& s : segments)
    lifted.push_back({Vec3(s[0].x(), s[0].y(), 0.025), Vec3(s[1].x(), s[1].y(), 0.025)});
  fill_lines(pd, lifted);
}

void set_direct_colours(vtkActor* actor, vtkPolyData* pd, bool filled = false) {
  vtkNew<vtkPolyDataMapper> mapper;
  if (filled) {
    // Polygons cut into triangles by ear clipping: OpenGL fills a concave polygon (a block
    // whose edge follows an opening's arc) as a fan from its first corner, across the opening.
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputData(pd);
    mapper->SetInputConnection(triangles->GetOutputPort());
  } else {
    mapper->SetInputData(pd);
  }
  mapper->SetColorModeToDirectScalars();
  mapper->SetScalarModeToUseCellData();
  actor->SetMapper(mapper);
}

// Lines in one colour and width (arrows, rubber band, previews, selection).
void set_line_colour(vtkActor* actor, vtkPolyData* pd, double r, double g, double b, double width) {
  set_direct_colours(actor, pd);
  actor->GetMapper()->ScalarVisibilityOff();
  actor->GetProperty()->SetColor(r, g, b);
  actor->GetProperty()->SetLineWidth(static_cast<float>(width));
}

// A colour bar for a legend: the ramp labelled at round values, or named colours.
void set_legend(vtkScalarBarActor* bar, const Legend& L) {
  vtkNew<vtkLookupTable> lut;
  if (L.continuous) {
    lut->SetNumberOfTableValues(kRampSamples);
    for (int i = 0; i < kRampSamples; ++i) {
      const Rgb c = ramp(i / double(kRampSamples - 1));
      lut->SetTableValue(i, c.r / 255.0, c.g / 255.0, c.b / 255.0);
    }
    lut->SetRange(L.lo, L.hi);
    vtkNew<vtkDoubleArray> ticks;
    for (double v : round_ticks(L.lo, L.hi)) ticks->InsertNextValue(v);
    bar->SetCustomLabels(ticks);
    bar->UseCustomLabelsOn();
    bar->SetLabelFormat("%g");
  } else {
    bar->UseCustomLabelsOff();
    lut->IndexedLookupOn();
    lut->SetNumberOfTableValues(static_cast<vtkIdType>(L.entries.size()));
    for (size_t i = 0; i < L.entries.size(); ++i) {
      const Rgb c = L.entries[i].second;
      lut->SetTableValue(static_cast<vtkIdType>(i), c.r / 255.0, c.g / 255.0, c.b / 255.0);
      lut->SetAnnotation(vtkVariant(static_cast<int>(i)), L.entries[i].first);
    }
  }
  lut->Build();
  bar->SetLookupTable(lut);
  bar->SetTitle(L.title.c_str());
  bar->SetVisibility(!L.title.empty() && (L.continuous || !L.entries.empty()));
}

void style_text(vtkTextActor* t, int size, bool bold) {
  t->GetTextProperty()->SetColor(0, 0, 0);
  t->GetTextProperty()->SetFontSize(size);
  t->GetTextProperty()->SetBold(bold);
}
}  // namespace

VtkView::VtkView(QWidget* parent) : QOpenGLWidget(parent) {
  window_ = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  window_->SetOwnContext(false);
  window_->SetFrameBlitModeToBlitToCurrent();
  // The model in its own viewport on a second layer, over a frame that holds the title, caption
  // and colour bars in margins the model never covers, however it is zoomed or panned.
  window_->SetNumberOfLayers(4);
  window_->AddRenderer(frame_);
  window_->AddRenderer(renderer_);
  frame_->SetLayer(0);
  frame_->SetBackground(1, 1, 1);
  frame_->InteractiveOff();
  renderer_->SetLayer(1);
  renderer_->SetViewport(kModelViewport[0], kModelViewport[1], kModelViewport[2],
                         kModelViewport[3]);
  renderer_->GetActiveCamera()->ParallelProjectionOn();
  // 3D support over the model: the same camera and viewport, its own depth.
  overlay_->SetLayer(2);
  overlay_->SetViewport(kModelViewport[0], kModelViewport[1], kModelViewport[2], kModelViewport[3]);
  overlay_->SetActiveCamera(renderer_->GetActiveCamera());
  overlay_->InteractiveOff();
  overlay_->AddActor(support_actor_);
  window_->AddRenderer(overlay_);
  // 3D: the triad in the lower left corner, over the frame (its own layer, its own depth).
  triad_->SetLayer(3);
  triad_->SetViewport(0.0, 0.1, 0.15, 0.3);
  triad_->InteractiveOff();
  triad_->AddActor(triad_axes_);
  triad_->SetDraw(false);
  window_->AddRenderer(triad_);
  triad_axes_->SetXAxisLabelText("E");
  triad_axes_->SetYAxisLabelText("N");
  triad_axes_->SetZAxisLabelText("Up");
  triad_axes_->SetShaftTypeToCylinder();
  triad_axes_->SetCylinderRadius(0.03);
  triad_axes_->SetConeRadius(0.35);
  triad_axes_->SetTotalLength(1, 1, 1);
  for (vtkCaptionActor2D* label :
       {triad_axes_->GetXAxisCaptionActor2D(), triad_axes_->GetYAxisCaptionActor2D(),
        triad_axes_->GetZAxisCaptionActor2D()}) {
    label->GetTextActor()->SetTextScaleModeToNone();
    label->GetCaptionTextProperty()->SetFontSize(14);
    label->GetCaptionTextProperty()->SetColor(0, 0, 0);
    label->GetCaptionTextProperty()->ShadowOff();
    label->GetCaptionTextProperty()->ItalicOff();
  }
  picker_->SetTolerance(0.002);
  picker_->PickFromListOn();
  picker_->AddPickList(blocks_actor_);
  picker_->AddPickList(bars_actor_);
  // Faces a hair behind the outlines and contact squares drawn on them.
  vtkMapper::SetResolveCoincidentTopologyToPolygonOffset();
  set_direct_colours(blocks_actor_, blocks_, true);
  set_direct_colours(zones_actor_, zones_, true);
  set_direct_colours(edges_actor_, edges_);
  edges_actor_->GetMapper()->ScalarVisibilityOff();
  edges_actor_->GetProperty()->SetRepresentationToWireframe();
  edges_actor_->GetProperty()->SetColor(0.25, 0.25, 0.25);
  set_direct_colours(bars_actor_, bars_, true);
  // 3D sub-contacts lie on the faces they join: drawn a hair in front.
  bars_actor_->GetMapper()->SetRelativeCoincidentTopologyPolygonOffsetParameters(-2, -2);
  set_line_colour(arrows_actor_, arrows_, 0, 0, 0, 1.5);
  set_direct_colours(support_actor_, support_);
  support_actor_->GetProperty()->SetLineWidth(4.0f);
  support_actor_->GetProperty()->SetRenderLinesAsTubes(true);
  support_actor_->GetProperty()->LightingOff();
  set_line_colour(band_actor_, band_, 0.85, 0.1, 0.1, 2.0);
  band_actor_->GetProperty()->SetPointSize(7.0);
  set_line_colour(preview_actor_, preview_, 0.1, 0.3, 0.9, 1.5);
  set_line_colour(highlight_actor_, highlight_, 1.0, 0.55, 0.0, 3.0);
  for (vtkActor* a :
       {blocks_actor_.Get(), zones_actor_.Get(), edges_actor_.Get(), bars_actor_.Get(),
        arrows_actor_.Get(), band_actor_.Get(), preview_actor_.Get(), highlight_actor_.Get()}) {
    // A flat 2D picture: colours as given, no shading (3D faces: rebuild).
    a->GetProperty()->LightingOff();
    a->GetProperty()->SetAmbient(0.6);
    a->GetProperty()->SetDiffuse(0.4);
    renderer_->AddActor(a);
  }
  for (vtkScalarBarActor* bar : {scalar_bar_.Get(), contacts_bar_.Get(), support_bar_.Get()}) {
    bar->SetNumberOfLabels(5);
    bar->UnconstrainedFontSizeOn();
    bar->VisibilityOff();
    bar->SetWidth(0.1);
    for (vtkTextProperty* t : {bar->GetTitleTextProperty(), bar->GetLabelTextProperty(),
                               bar->GetAnnotationTextProperty()}) {
      t->SetColor(0, 0, 0);
      t->ItalicOff();
      t->ShadowOff();
      t->BoldOff();
      t->SetFontSize(13);
    }
    frame_->AddActor2D(bar);
  }
  // Axes along the left and bottom edges labelled in model coordinates (metres).
  // Axes along the model viewport's left and bottom edges, in the frame's margin, labelled in
  // model coordinates (metres) at round values (placed before every render: placeAxes).
  for (vtkAxisActor2D* axis : {x_axis_.Get(), y_axis_.Get()}) {
    axis->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
    axis->GetPosition2Coordinate()->SetCoordinateSystemToDisplay();
    axis->AdjustLabelsOff();
    axis->SetLabelFormat("%g");
    axis->TitleVisibilityOff();
    axis->SetTickLength(6);
    axis->SetMinorTickLength(3);
    axis->SetNumberOfMinorTicks(0);
    axis->SetFontFactor(1.0);
    axis->GetProperty()->SetColor(0, 0, 0);
    axis->GetLabelTextProperty()->SetColor(0, 0, 0);
    axis->GetLabelTextProperty()->ItalicOff();
    axis->GetLabelTextProperty()->ShadowOff();
    axis->GetLabelTextProperty()->BoldOff();
    axis->GetLabelTextProperty()->SetFontSize(12);
    axis->VisibilityOff();
    frame_->AddActor2D(axis);
  }
  style_text(title_, 18, true);
  title_->SetTextScaleModeToNone();
  title_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  title_->GetTextProperty()->SetJustificationToCentered();
  title_->GetTextProperty()->SetVerticalJustificationToTop();
  title_->SetPosition(0.5, 0.97);
  style_text(caption_, 12, false);
  caption_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  caption_->SetPosition(0.01, 0.01);
  frame_->AddActor2D(title_);
  frame_->AddActor2D(caption_);
  setMouseTracking(false);
  setFocusPolicy(Qt::StrongFocus);
}

void VtkView::setDefaultSurfaceFormat() {
  QSurfaceFormat f;
  f.setRenderableType(QSurfaceFormat::OpenGL);
  f.setVersion(3, 2);
  f.setProfile(QSurfaceFormat::CoreProfile);
  f.setDepthBufferSize(24);
  f.setStencilBufferSize(8);
  f.setSwapBehavior(QSurfaceFormat::DoubleBuffer);
  QSurfaceFormat::setDefaultFormat(f);
}

VtkView::~VtkView() {
  makeCurrent();
  window_->Finalize();
  doneCurrent();
}

void VtkView::initializeGL() {
  window_->OpenGLInitContext();
}

void VtkView::resizeGL(int w, int h) {
  const double r = devicePixelRatioF();
  window_->SetSize(static_cast<int>(w * r), static_cast<int>(h * r));
}

std::string VtkView::captionShown() const {
  return caption_->GetInput() ? caption_->GetInput() : "";
}

bool VtkView::contactScaleShown() const {
  return contacts_bar_->GetVisibility() != 0;
}

bool VtkView::supportScaleShown() const {
  return support_bar_->GetVisibility() != 0;
}

void VtkView::placeAxes() {
  // Axes in model coordinates mean nothing on a 3D view (its scale bar is in the caption).
  const bool shown = has_scene_ && !scene_.three && width() > 0 && height() > 0;
  x_axis_->SetVisibility(shown);
  y_axis_->SetVisibility(shown);
  if (!shown) return;
  Vec2 lo, hi;
  visibleWindow(lo, hi);
  const double r = devicePixelRatioF(), w = width() * r, h = height() * r;
  const double x0 = kModelViewport[0] * w, x1 = kModelViewport[2] * w, y0 = kModelViewport[1] * h,
               y1 = kModelViewport[3] * h;
  const std::vector<double> xs = round_ticks(lo.x(), hi.x(), 7),
                            ys = round_ticks(lo.y(), hi.y(), 7);
  const auto dx = [&](double x) { return x0 + (x - lo.x()) / (hi.x() - lo.x()) * (x1 - x0); };
  const auto dy = [&](double y) { return y0 + (y - lo.y()) / (hi.y() - lo.y()) * (y1 - y0); };
  // Each axis runs between its first and last round value, ticks and labels on its outer side
  // (the right of its direction): the bottom one left to right, the left one top to bottom.
  x_axis_->GetPositionCoordinate()->SetValue(dx(xs.front()), y0 - 2);
  x_axis_->GetPosition2Coordinate()->SetValue(dx(xs.back()), y0 - 2);
  x_axis_->SetRange(xs.front(), xs.back());
  x_axis_->SetNumberOfLabels(static_cast<int>(xs.size()));
  x_ticks_ = xs, y_ticks_ = ys;
  y_axis_->GetPositionCoordinate()->SetValue(x0 + 2, dy(ys.back()));
  y_axis_->GetPosition2Coordinate()->SetValue(x0 + 2, dy(ys.front()));
  y_axis_->SetRange(ys.back(), ys.front());
  y_axis_->SetNumberOfLabels(static_cast<int>(ys.size()));
}

void VtkView::paintGL() {
  placeAxes();
  placeCaption();
  placeTriad();
  window_->SetReadyForRendering(true);
  window_->SetIsCurrent(true);
  window_->Render();
}

void VtkView::showScene(const Scene& scene, bool fit) {
  const bool first = !has_scene_ || scene.three != scene_.three;
  scene_ = scene;
  has_scene_ = true;
  rebuild();
  // A 3D scene built for another view (the options changed) turns the camera there, except
  // while the user is turning it (frames of a run keep coming; the window learns the new view
  // on release).
  const bool turning = button_ == Qt::RightButton && dragged_;
  const bool turn =
      scene_.three && !turning && (scene_.azimuth != azimuth_ || scene_.elevation != elevation_);
  if (scene_.three && !turning) azimuth_ = scene_.azimuth, elevation_ = scene_.elevation;
  if (first || fit)
    resetCamera();
  else if (turn)
    aimCamera();
  update();
}

void VtkView::rebuild() {
  // Lit by the camera's headlight in 3D (ambient 0.6, diffuse 0.4: the figures' shading),
  // flat colours in 2D.
  blocks_actor_->GetProperty()->SetLighting(scene_.three);
  blocks_actor_->GetProperty()->SetOpacity(scene_.three && see_through_ ? 0.25 : 1.0);
  if (scene_.three) {
    rebuild3();
  } else {
    std::vector<std::vector<Vec2>> polys;
    std::vector<Rgb> colours;
    for (const auto& p : scene_.polygons) polys.push_back(p.points), colours.push_back(p.colour);
    in_place_ += fill_polygons(blocks_, at_height(polys, 0.0), colours);
    // Block outlines above the zones, which sit above the block fills.
    fill_polygons(edges_, at_height(polys, 0.006), colours);
    std::vector<std::array<Vec2, 2>> outline = highlight_segments_;
    for (const auto& p : scene_.polygons)
      if (std::find(highlight_blocks_.begin(), highlight_blocks_.end(), p.block) !=
          highlight_blocks_.end())
        for (size_t k = 0; k < p.points.size(); ++k)
          outline.push_back({p.points[k], p.points[(k + 1) % p.points.size()]});
    fill_segments(highlight_, outline);
    polys.clear(), colours.clear();
    for (const auto& p : scene_.zones) polys.push_back(p.points), colours.push_back(p.colour);
    fill_polygons(zones_, at_height(polys, 0.003), colours);
    polys.clear(), colours.clear();
    for (const auto& b : scene_.bars)
      polys.push_back({b.corners[0], b.corners[1], b.corners[2], b.corners[3]}),
          colours.push_back(b.colour);
    fill_polygons(bars_, at_height(polys, 0.01), colours);
    fill_lines(support_, {});
    // Arrows as line cells: shaft and two head strokes.
    std::vector<std::array<Vec3, 2>> strokes;
    const auto line = [&](Vec2 a, Vec2 b) {
      strokes.push_back({Vec3(a.x(), a.y(), 0.02), Vec3(b.x(), b.y(), 0.02)});
    };
    for (const auto& a : scene_.arrows) {
      const Vec2 d = a.head - a.tail;
      const Vec2 n(-d.y(), d.x());
      line(a.tail, a.head);
      line(a.head, a.head - 0.25 * d + 0.12 * n);
      line(a.head, a.head - 0.25 * d - 0.12 * n);
    }
    fill_lines(arrows_, strokes);
  }
  // Legends: the blocks' (or zones') colours, and the contacts' when they are continuous too
  // (zones by stress, contacts by force: each its own scale), one above the other.
  const bool both = scene_.contacts_legend.continuous && !scene_.contacts_legend.title.empty() &&
                    scene_.blocks_legend.continuous;
  const Legend& L = scene_.blocks_legend.continuous || !scene_.contacts_legend.continuous
                        ? scene_.blocks_legend
                        : scene_.contacts_legend;
  // The support's force scale, when shown, takes the bottom third.
  const bool support = scene_.support_legend.continuous;
  const double top = 0.9, bottom = support ? 0.36 : 0.08;
  const double h = both ? (top - bottom) / 2.0 - 0.02 : top - bottom - 0.05;
  set_legend(scalar_bar_, L);
  scalar_bar_->SetPosition(0.87, top - h);
  scalar_bar_->SetHeight(h);
  contacts_bar_->SetVisibility(both);
  if (both) {
    set_legend(contacts_bar_, scene_.contacts_legend);
    contacts_bar_->SetPosition(0.87, bottom);
    contacts_bar_->SetHeight(h);
  }
  support_bar_->SetVisibility(support);
  if (support) {
    set_legend(support_bar_, scene_.support_legend);
    support_bar_->SetPosition(0.87, 0.06);
    support_bar_->SetHeight(0.26);
  }
  title_->SetInput(scene_.title.c_str());
  renderer_->ResetCameraClippingRange();
}

void VtkView::placeCaption() {
  // Wrapped to the window's width at the breaks between its items (three spaces), or between
  // words when one item is too long.
  const size_t chars = static_cast<size_t>(std::max(20.0, width() / 6.3));
  std::string out, line;
  const auto flush = [&] {
    if (!out.empty()) out += '\n';
    out += line, line.clear();
  };
  const std::string& text = scene_.caption;
  for (size_t at = 0; at < text.size();) {
    size_t next = text.find("   ", at);
    if (next == std::string::npos) next = text.size();
    std::string item = text.substr(at, next - at);
    at = std::min(text.size(), next + 3);
    if (item.empty()) continue;
    if (!line.empty() && line.size() + 3 + item.size() > chars) flush();
    while (item.size() > chars) {
      size_t cut = item.rfind(' ', chars);
      if (cut == std::string::npos || cut == 0) cut = chars;
      if (!line.empty()) flush();
      line = item.substr(0, cut);
      flush();
      item = item.substr(std::min(item.size(), cut + 1));
    }
    line += (line.empty() ? "" : "   ") + item;
  }
  if (!line.empty()) flush();
  caption_->SetInput(out.c_str());
}

void VtkView::resetCamera() {
  if (scene_.three) return resetCamera3();
  vtkCamera* cam = renderer_->GetActiveCamera();
  cam->ParallelProjectionOn();
  const Vec2 mid = 0.5 * (scene_.lo + scene_.hi), span = scene_.hi - scene_.lo;
  cam->SetFocalPoint(mid.x(), mid.y(), 0);
  cam->SetPosition(mid.x(), mid.y(), 10 * std::max(span.x(), span.y()) + 1);
  cam->SetViewUp(0, 1, 0);
  // The model's viewport (the frame's margins hold title, caption and colour bars), with room
  // for the scale axes along its left and bottom edges.
  const double w = width() * (kModelViewport[2] - kModelViewport[0]),
               h = height() * (kModelViewport[3] - kModelViewport[1]);
  const double aspect = h > 0 ? w / h : 1.0;
  cam->SetParallelScale(0.58 * std::max(span.y(), span.x() / aspect));
  renderer_->ResetCameraClippingRange();
  update();
}

Vec2 VtkView::modelPoint(const QPoint& pixel) {
  const double r = devicePixelRatioF();
  renderer_->SetDisplayPoint(pixel.x() * r, (height() - pixel.y()) * r, 0);
  renderer_->DisplayToWorld();
  const double* w = renderer_->GetWorldPoint();
  return {w[0] / w[3], w[1] / w[3]};
}

QPoint VtkView::pixelOf(Vec2 p) {
  renderer_->SetWorldPoint(p.x(), p.y(), 0, 1);
  renderer_->WorldToDisplay();
  const double* d = renderer_->GetDisplayPoint();
  const double r = devicePixelRatioF();
  return {static_cast<int>(std::lround(d[0] / r)),
          static_cast<int>(std::lround(height() - d[1] / r))};
}

void VtkView::visibleWindow(Vec2& lo, Vec2& hi) {
  if (scene_.three) return visibleWindow3(lo, hi);
  // The corners of the model's viewport.
  const QPoint low(static_cast<int>(kModelViewport[0] * width()),
                   static_cast<int>((1 - kModelViewport[1]) * height())),
      high(static_cast<int>(kModelViewport[2] * width()),
           static_cast<int>((1 - kModelViewport[3]) * height()));
  const Vec2 a = modelPoint(low), b = modelPoint(high);
  lo = a.cwiseMin(b), hi = a.cwiseMax(b);
}

void VtkView::setDrawing(DrawMode mode, double grid) {
  drawing_.start(mode);
  grid_ = grid;
  const bool shapes = mode == DrawMode::kBlock || mode == DrawMode::kCrack;
  setMouseTracking(shapes);
  setCursor(mode != DrawMode::kNone ? Qt::CrossCursor : Qt::ArrowCursor);
  showDrawing(QPoint(-1, -1));
}

void VtkView::setPreview(const std::vector<std::array<Vec2, 2>>& segments) {
  fill_segments(preview_, segments);
  preview_count_ = segments.size();
  update();
}

void VtkView::setHighlight(const std::vector<int>& blocks,
                           const std::vector<std::array<Vec2, 2>>& segments) {
  highlight_blocks_ = blocks;
  highlight_segments_ = segments;
  rebuild();
  update();
}

void VtkView::showDrawing(const QPoint& cursor) {
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> lines, verts;
  std::vector<Vec2> chain = drawing_.points();
  const bool shapes = drawing_.mode() == DrawMode::kBlock || drawing_.mode() == DrawMode::kCrack;
  if (shapes && cursor.x() >= 0) {
    const Vec2 at = modelPoint(cursor);
    const double reach = (modelPoint(cursor + QPoint(8, 0)) - at).norm();
    chain.push_back(Drawing::snap(at, scene_, grid_, reach));
  }
  for (const Vec2& v : chain) {
    const vtkIdType id = pts->InsertNextPoint(v.x(), v.y(), 0.03);
    verts->InsertNextCell(1, &id);
  }
  for (vtkIdType i = 0; i + 1 < pts->GetNumberOfPoints(); ++i) {
    const vtkIdType ids[2] = {i, i + 1};
    lines->InsertNextCell(2, ids);
  }
  // A block closes back to its first point.
  if (drawing_.mode() == DrawMode::kBlock && pts->GetNumberOfPoints() >= 3) {
    const vtkIdType ids[2] = {pts->GetNumberOfPoints() - 1, 0};
    lines->InsertNextCell(2, ids);
  }
  band_->Initialize();
  band_->SetPoints(pts);
  band_->SetLines(lines);
  band_->SetVerts(verts);
  update();
}

void VtkView::finishDrawing() {
  if (!drawing_.complete()) return;
  QVector<QPointF> points;
  for (const Vec2& v : drawing_.points()) points.append(QPointF(v.x(), v.y()));
  const DrawMode mode = drawing_.mode();
  drawing_.start(mode);  // ready for the next shape with the same tool
  showDrawing(QPoint(-1, -1));
  emit drawn(mode, points);
}

void VtkView::mouseDoubleClickEvent(QMouseEvent* e) {
  const bool shapes = drawing_.mode() == DrawMode::kBlock || drawing_.mode() == DrawMode::kCrack;
  if (!shapes || e->button() != Qt::LeftButton) return QOpenGLWidget::mouseDoubleClickEvent(e);
  // The point under the double click (already placed if its first click was delivered: a repeat
  // is ignored).
  const Vec2 at = modelPoint(e->pos());
  const double reach = (modelPoint(e->pos() + QPoint(8, 0)) - at).norm();
  drawing_.add(Drawing::snap(at, scene_, grid_, reach));
  finishDrawing();
  button_ = Qt::NoButton;
}

bool VtkView::finishShape() {
  const bool shapes = drawing_.mode() == DrawMode::kBlock || drawing_.mode() == DrawMode::kCrack;
  if (!shapes || drawing_.points().empty()) return false;
  finishDrawing();
  return true;
}

void VtkView::keyPressEvent(QKeyEvent* e) {
  const bool shapes = drawing_.mode() == DrawMode::kBlock || drawing_.mode() == DrawMode::kCrack;
  if (shapes && (e->key() == Qt::Key_Return || e->key() == Qt::Key_Enter)) {
    finishDrawing();
  } else if (shapes && e->key() == Qt::Key_Escape) {
    drawing_.cancel();
    showDrawing(QPoint(-1, -1));
  } else {
    QOpenGLWidget::keyPressEvent(e);
  }
}

void VtkView::mousePressEvent(QMouseEvent* e) {
  press_ = last_ = e->pos();
  button_ = e->button();
  dragged_ = false;
}

void VtkView::mouseMoveEvent(QMouseEvent* e) {
  if (button_ == Qt::NoButton) {
    if (drawing_.mode() != DrawMode::kNone) showDrawing(e->pos());
    return;
  }
  const QPoint d = e->pos() - last_;
  if ((e->pos() - press_).manhattanLength() > 3) dragged_ = true;
  if (scene_.three) {
    // 3D: a right drag turns the camera about the vertical and tilts it (the window learns the
    // new view on release), the other buttons pan.
    if (button_ == Qt::LeftButton && drawing_.mode() == DrawMode::kSelect) {
      if (!rubber_) rubber_ = new QRubberBand(QRubberBand::Rectangle, this);
      rubber_->setGeometry(QRect(press_, e->pos()).normalized());
      rubber_->show();
    } else if (button_ == Qt::RightButton) {
      azimuth_ = std::fmod(azimuth_ - 0.4 * d.x() + 360.0, 360.0);
      elevation_ = std::clamp(elevation_ + 0.4 * d.y(), -89.0, 89.0);
      aimCamera();
    } else {
      pan3(last_, e->pos());
    }
    last_ = e->pos();
    update();
    return;
  }
  vtkCamera* cam = renderer_->GetActiveCamera();
  if (button_ == Qt::LeftButton && drawing_.mode() == DrawMode::kSelect) {
    // The selection box, corner to corner.
    const Vec2 a = modelPoint(press_), b = modelPoint(e->pos());
    fill_segments(band_, {{{a, Vec2(b.x(), a.y())}},
                          {{Vec2(b.x(), a.y()), b}},
                          {{b, Vec2(a.x(), b.y())}},
                          {{Vec2(a.x(), b.y()), a}}});
  } else if (button_ == Qt::LeftButton || button_ == Qt::MiddleButton) {
    // Pan: move the camera by the model distance the cursor moved.
    const Vec2 a = modelPoint(last_), b = modelPoint(e->pos());
    const Vec2 shift = a - b;
    double f[3], p[3];
    cam->GetFocalPoint(f), cam->GetPosition(p);
    cam->SetFocalPoint(f[0] + shift.x(), f[1] + shift.y(), f[2]);
    cam->SetPosition(p[0] + shift.x(), p[1] + shift.y(), p[2]);
  } else if (button_ == Qt::RightButton) {
    cam->Azimuth(-0.4 * d.x());
    cam->Elevation(0.4 * d.y());
    cam->OrthogonalizeViewUp();
  }
  last_ = e->pos();
  renderer_->ResetCameraClippingRange();
  update();
}

void VtkView::mouseReleaseEvent(QMouseEvent* e) {
  if (scene_.three && has_scene_) {
    const Qt::MouseButton button = button_;
    button_ = Qt::NoButton;
    if (button == Qt::RightButton && dragged_) emit turned(azimuth_, elevation_);
    if (button == Qt::LeftButton && dragged_ && drawing_.mode() == DrawMode::kSelect) {
      if (rubber_) rubber_->hide();
      emit blocksBoxed(blocksIn(QRect(press_, e->pos()).normalized()));
    }
    if (button == Qt::LeftButton && !dragged_) pick3(e->pos());
    return;
  }
  if (drawing_.mode() == DrawMode::kSelect && button_ == Qt::LeftButton && dragged_) {
    const Vec2 a = modelPoint(press_), b = modelPoint(e->pos());
    fill_segments(band_, {});
    button_ = Qt::NoButton;
    update();
    emit boxSelected(QPointF(std::min(a.x(), b.x()), std::min(a.y(), b.y())),
                     QPointF(std::max(a.x(), b.x()), std::max(a.y(), b.y())));
    return;
  }
  const bool shapes = drawing_.mode() == DrawMode::kBlock || drawing_.mode() == DrawMode::kCrack;
  if (shapes && !dragged_) {
    // A click places a snapped point; a right click drops the shape.
    if (button_ == Qt::LeftButton) {
      const Vec2 at = modelPoint(e->pos());
      const double reach = (modelPoint(e->pos() + QPoint(8, 0)) - at).norm();
      drawing_.add(Drawing::snap(at, scene_, grid_, reach));
    } else if (button_ == Qt::RightButton) {
      drawing_.cancel();
    }
    showDrawing(e->pos());
    button_ = Qt::NoButton;
    return;
  }
  if (!dragged_ && button_ == Qt::LeftButton && has_scene_) {
    const Vec2 p = modelPoint(e->pos());
    const int contact = bar_at(scene_, p);
    // The select tool: an outline edge of a deformable block near the click (boundary edges
    // take stresses and conditions), unless a contact bar is under it.
    if (drawing_.mode() == DrawMode::kSelect && contact < 0) {
      const double reach = (modelPoint(e->pos() + QPoint(5, 0)) - p).norm();
      double best = reach;
      int block = -1;
      Vec2 ea, eb;
      for (const auto& poly : scene_.polygons) {
        if (poly.block < 0 || !scene_.deformable(poly.block)) continue;
        for (size_t k = 0; k < poly.points.size(); ++k) {
          const Vec2 a = poly.points[k], b = poly.points[(k + 1) % poly.points.size()];
          const double t =
              std::clamp((p - a).dot(b - a) / std::max((b - a).squaredNorm(), 1e-300), 0.0, 1.0);
          if (const double d = (a + t * (b - a) - p).norm(); d < best)
            best = d, block = poly.block, ea = a, eb = b;
        }
      }
      if (block >= 0) {
        button_ = Qt::NoButton;
        emit edgePicked(block, QPointF(ea.x(), ea.y()), QPointF(eb.x(), eb.y()));
        return;
      }
    }
    emit picked(contact >= 0 ? -1 : block_at(scene_, p), contact);
    if (const int zone = contact >= 0 ? -1 : zone_at(scene_, p); zone >= 0) emit zonePicked(zone);
  }
  button_ = Qt::NoButton;
}

void VtkView::wheelEvent(QWheelEvent* e) {
  // Zoom about the cursor: the model point under it stays put.
  vtkCamera* cam = renderer_->GetActiveCamera();
  const QPoint at = e->position().toPoint();
  if (scene_.three) {
    zoom3(at, std::pow(0.85, e->angleDelta().y() / 120.0));
    update();
    return;
  }
  const Vec2 before = modelPoint(at);
  cam->SetParallelScale(cam->GetParallelScale() * std::pow(0.85, e->angleDelta().y() / 120.0));
  const Vec2 shift = before - modelPoint(at);
  double f[3], p[3];
  cam->GetFocalPoint(f), cam->GetPosition(p);
  cam->SetFocalPoint(f[0] + shift.x(), f[1] + shift.y(), f[2]);
  cam->SetPosition(p[0] + shift.x(), p[1] + shift.y(), p[2]);
  update();
}

}  // namespace tessera::ui
