// The model viewport: VTK drawing a Scene inside a QOpenGLWidget.
//
// Debian's VTK Qt module is built for Qt5, so VTK is embedded by hand: a
// vtkGenericOpenGLRenderWindow that draws into the widget's context (the recipe in
// shared/DESIGN.md). Mouse: left drag pans, wheel zooms, right drag turns the view (a 3D model
// about the vertical, north kept in the triad), a click picks the block or contact under the
// cursor (3D: VTK's cell picker on the faces and sub-contacts). 3D models are drawn in model
// coordinates through a VTK camera (parallel or perspective), lit by a headlight. With a drawing
// tool on, clicks
// place snapped points (a rubber band shows the shape), a double click or Enter finishes the
// shape, Escape or a right click drops it. With the select tool, a left drag draws a box (the
// middle button pans in every mode).
#pragma once

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <QOpenGLWidget>
#include <array>
#include <vector>

#include "tessera/ui/draw_tool.hpp"
#include "tessera/ui/scene.hpp"

class vtkActor;
class vtkAxesActor;
class vtkCellPicker;
class vtkGenericOpenGLRenderWindow;
class vtkAxisActor2D;
class vtkPolyData;
class vtkRenderer;
class vtkScalarBarActor;
class vtkTextActor;
class QRubberBand;

namespace tessera::ui {

class VtkView : public QOpenGLWidget {
  Q_OBJECT
 public:
  explicit VtkView(QWidget* parent = nullptr);
  ~VtkView() override;
  // The OpenGL context VTK needs (3.2 core, depth and stencil); call before QApplication.
  static void setDefaultSurfaceFormat();

  // Shows a new scene; the camera keeps its place unless this is the first or `fit` is set.
  void showScene(const Scene& scene, bool fit = false);
  const Scene& scene() const { return scene_; }
  // Fits the camera to the scene.
  void resetCamera();
  // The model point under a widget pixel (2D views).
  Vec2 modelPoint(const QPoint& pixel);
  // The widget pixel a model point is drawn at (2D views).
  QPoint pixelOf(Vec2 p);
  // The model window the camera shows now, for figures of the current view (3D: in the view
  // coordinates of the figures' projection).
  void visibleWindow(Vec2& lo, Vec2& hi);
  // Turns a drawing tool on (kNone: off), snapping to a grid of this spacing (0: none) and to
  // block vertices within 8 pixels.
  void setDrawing(DrawMode mode, double grid);
  const Drawing& drawing() const { return drawing_; }
  // Finishes the shape being drawn, as Enter in the view does; false if none is under way.
  bool finishShape();
  // Lines drawn over the model to preview a cut before it is made (empty: none).
  void setPreview(const std::vector<std::array<Vec2, 2>>& segments);
  // The same in model coordinates, for 3D models.
  void setPreview3(const std::vector<std::array<Vec3, 2>>& segments);
  size_t previewSegments() const { return preview_count_; }
  // Frames whose block faces were updated in VTK's arrays in place (the same faces moved or
  // recoloured, as during a run) rather than rebuilt.
  size_t updatedInPlace() const { return in_place_; }
  // Whether the contacts have a colour bar of their own (beside the blocks' or zones').
  bool contactScaleShown() const;
  // Whether the support's axial force scale is shown (bolts and cables coloured by force).
  bool supportScaleShown() const;
  // The caption as drawn (wrapped to the window).
  std::string captionShown() const;
  // The values the axes are labelled at, as last drawn (2D views).
  const std::vector<double>& xTicks() const { return x_ticks_; }
  const std::vector<double>& yTicks() const { return y_ticks_; }
  // 3D: perspective or parallel projection (parallel by default).
  void setPerspective(bool on);
  bool perspective() const;
  // 3D: the camera's focal point and the eye's distance from it, for figures of this view.
  void camera3(Vec3& focus, double& distance);
  // 3D: block faces drawn translucent, so that the sub-contacts inside show.
  void setSeeThrough(bool on);
  bool seeThrough() const;
  // 3D: where the camera looks from now (degrees; the scene's view until the user turns it).
  double azimuth() const { return azimuth_; }
  double elevation() const { return elevation_; }
  // Blocks (scene indices) and segments outlined as selected.
  void setHighlight(const std::vector<int>& blocks,
                    const std::vector<std::array<Vec2, 2>>& segments = {});

 signals:
  void picked(int block, int contact);
  // After `picked`: the zone under the click, when zones are drawn in their colours.
  void zonePicked(int zone);
  // A finished shape, as the script command that makes it (group and material added by the
  // window).
  void drawn(DrawMode mode, const QVector<QPointF>& points);
  // The select tool's box, in model coordinates.
  void boxSelected(QPointF lo, QPointF hi);
  // 3D: the blocks (scene indices) whose centroids lie in the select tool's box on the screen.
  void blocksBoxed(const QVector<int>& blocks);
  // A right drag over a 3D model ended with the camera looking from here (degrees).
  void turned(double azimuth, double elevation);
  // The select tool clicked within a few pixels of a deformable block's outline edge.
  void edgePicked(int block, QPointF a, QPointF b);

 protected:
  void initializeGL() override;
  void paintGL() override;
  void resizeGL(int w, int h) override;
  void mousePressEvent(QMouseEvent* e) override;
  void mouseMoveEvent(QMouseEvent* e) override;
  void mouseReleaseEvent(QMouseEvent* e) override;
  void wheelEvent(QWheelEvent* e) override;
  void mouseDoubleClickEvent(QMouseEvent* e) override;
  void keyPressEvent(QKeyEvent* e) override;

 private:
  void rebuild();
  // The axes at round model coordinates along the model viewport's edges, for the camera now.
  void placeAxes();
  // The caption wrapped to the window's width.
  void placeCaption();
  // The rubber band: the drawn points and the cursor.
  void showDrawing(const QPoint& cursor);
  void finishDrawing();
  // 3D (vtk_view3d.cpp): the scene's actors from world points; the camera aimed from azimuth_
  // and elevation_ at its focal point; fitted to the scene; panned and zoomed by pixels; the
  // triad turned with the camera; the block face or sub-contact under a pixel.
  void rebuild3();
  void aimCamera();
  void resetCamera3();
  void pan3(QPoint from, QPoint to);
  void zoom3(QPoint at, double factor);
  void placeTriad();
  void pick3(QPoint at);
  // The blocks whose centroids (the mean of their faces' corners) are drawn inside a rectangle.
  QVector<int> blocksIn(const QRect& r);
  void visibleWindow3(Vec2& lo, Vec2& hi);
  // Model metres per pixel on the focal plane.
  double worldPerPixel();

  vtkNew<vtkRenderer> renderer_;
  vtkSmartPointer<vtkGenericOpenGLRenderWindow> window_;
  vtkNew<vtkPolyData> blocks_, zones_, edges_, bars_, arrows_, band_, preview_, highlight_;
  vtkNew<vtkActor> blocks_actor_, zones_actor_, edges_actor_, bars_actor_, arrows_actor_,
      band_actor_, preview_actor_, highlight_actor_;
  std::vector<int> highlight_blocks_;
  std::vector<std::array<Vec2, 2>> highlight_segments_;
  size_t preview_count_ = 0;
  vtkNew<vtkRenderer> frame_;  // title, caption and colour bars around the model's viewport
  // The model's viewport in the window (x0, y0, x1, y1, normalized).
  static constexpr double kModelViewport[4] = {0.08, 0.12, 0.78, 0.93};
  vtkNew<vtkScalarBarActor> scalar_bar_, contacts_bar_, support_bar_;
  vtkNew<vtkAxisActor2D> x_axis_, y_axis_;
  std::vector<double> x_ticks_, y_ticks_;
  vtkNew<vtkTextActor> title_, caption_;
  // 3D support (cables) lies inside the rock: lines drawn over the model, by a renderer on the
  // model's camera and viewport, a layer above it.
  vtkNew<vtkRenderer> overlay_;
  vtkNew<vtkPolyData> support_;
  vtkNew<vtkActor> support_actor_;
  vtkNew<vtkRenderer> triad_;  // the axes triad (east, north, up), turned with the camera
  vtkNew<vtkAxesActor> triad_axes_;
  vtkNew<vtkCellPicker> picker_;
  std::vector<int> face_block_, face_zone_;  // 3D: the block (zone) each face drawn shows
  QRubberBand* rubber_ = nullptr;            // 3D: the select tool's box on the screen
  double azimuth_ = 210, elevation_ = 25;
  bool perspective_ = false, see_through_ = false;  // 3D settings (2D views ignore them)
  Scene scene_;
  bool has_scene_ = false;
  size_t in_place_ = 0;
  QPoint press_, last_;
  Qt::MouseButton button_ = Qt::NoButton;
  bool dragged_ = false;
  Drawing drawing_;
  double grid_ = 0;
};

}  // namespace tessera::ui
