// The model viewport: VTK drawing a Scene inside a QOpenGLWidget.
//
// Debian's VTK Qt module is built for Qt5, so VTK is embedded by hand: a
// vtkGenericOpenGLRenderWindow that draws into the widget's context (the recipe in
// shared/DESIGN.md). Mouse: left drag pans, wheel zooms, right drag turns the view (of a 3D
// model: the window turns the viewpoint and redraws the projected scene), a click picks the
// block or contact under the cursor. With a drawing tool on, clicks
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
class vtkGenericOpenGLRenderWindow;
class vtkAxisActor2D;
class vtkPolyData;
class vtkRenderer;
class vtkScalarBarActor;
class vtkTextActor;

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
  // The model window the camera shows now, for figures of the current view.
  void visibleWindow(Vec2& lo, Vec2& hi);
  // Turns a drawing tool on (kNone: off), snapping to a grid of this spacing (0: none) and to
  // block vertices within 8 pixels.
  void setDrawing(DrawMode mode, double grid);
  const Drawing& drawing() const { return drawing_; }
  // Finishes the shape being drawn, as Enter in the view does; false if none is under way.
  bool finishShape();
  // Lines drawn over the model to preview a cut before it is made (empty: none).
  void setPreview(const std::vector<std::array<Vec2, 2>>& segments);
  size_t previewSegments() const { return preview_count_; }
  // Whether the contacts have a colour bar of their own (beside the blocks' or zones').
  bool contactScaleShown() const;
  // The values the axes are labelled at, as last drawn (2D views).
  const std::vector<double>& xTicks() const { return x_ticks_; }
  const std::vector<double>& yTicks() const { return y_ticks_; }
  // Blocks (scene indices) and segments outlined as selected.
  void setHighlight(const std::vector<int>& blocks,
                    const std::vector<std::array<Vec2, 2>>& segments = {});

 signals:
  void picked(int block, int contact);
  // A finished shape, as the script command that makes it (group and material added by the
  // window).
  void drawn(DrawMode mode, const QVector<QPointF>& points);
  // The select tool's box, in model coordinates.
  void boxSelected(QPointF lo, QPointF hi);
  // A right drag over a 3D model: turn the viewpoint by these angles (degrees).
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
  // The rubber band: the drawn points and the cursor.
  void showDrawing(const QPoint& cursor);
  void finishDrawing();

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
  vtkNew<vtkScalarBarActor> scalar_bar_, contacts_bar_;
  vtkNew<vtkAxisActor2D> x_axis_, y_axis_;
  std::vector<double> x_ticks_, y_ticks_;
  vtkNew<vtkTextActor> title_, caption_;
  Scene scene_;
  bool has_scene_ = false;
  QPoint press_, last_;
  Qt::MouseButton button_ = Qt::NoButton;
  bool dragged_ = false;
  Drawing drawing_;
  double grid_ = 0;
};

}  // namespace tessera::ui
