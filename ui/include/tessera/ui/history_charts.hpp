// Live history charts (Qt Charts): one small chart per history series against cycles, each with
// its quantity and unit on the y axis; any of them enlarged in a window of its own, or plotted
// against another history (x-y: e.g. shear stress against shear displacement), live too.
#pragma once

#include <QPointer>
#include <QScrollArea>
#include <vector>

#include "tessera/ui/snapshot.hpp"

class QChartView;
class QDialog;
class QLineSeries;
class QValueAxis;
class QVBoxLayout;

namespace tessera::ui {

class HistoryCharts : public QScrollArea {
  Q_OBJECT
 public:
  explicit HistoryCharts(QWidget* parent = nullptr);
  // Replaces the curves with the snapshot's (rebuilding the charts if the series changed).
  void update(const Snapshot& s);
  int chartCount() const { return static_cast<int>(charts_.size()); }
  // Points in the curve of series i.
  int pointCount(int i) const;
  // The y axis title of chart i (the quantity and its unit).
  QString yTitle(int i) const;
  // Writes chart i to `path`: .png (its size on screen, at least 800 x 500), .svg, or .csv (the
  // x and y values shown). Each chart's right-click menu offers these. False if it cannot.
  bool exportChart(int i, const QString& path) const;
  // Series i in a window of its own against cycles (a double click does it), or against series
  // `x` (x-y); both follow the run. The window is the caller's to close.
  QDialog* enlarge(int i);
  QDialog* plotAgainst(int y, int x);
  // The windows open now, and the points of the curve in window k.
  int windowCount() const;
  QList<QPointF> windowPoints(int k) const;

 protected:
  bool eventFilter(QObject* watched, QEvent* e) override;

 private:
  struct Chart {
    QLineSeries* series = nullptr;
    QValueAxis *x = nullptr, *y = nullptr;
    QChartView* view = nullptr;
    int yi = 0, xi = -1;  // the series shown, against this one (-1: cycles)
  };
  // A chart of series yi against xi (or cycles), with its right-click menu.
  Chart makeChart(int yi, int xi);
  // Its points from the last snapshot, and axes at round values.
  void fill(Chart& c);
  bool exportTo(const Chart& c, const QString& path) const;
  QString axisTitle(int i) const;
  QDialog* openWindow(int yi, int xi);

  QWidget* box_;
  QVBoxLayout* layout_;
  std::vector<std::string> labels_, titles_;
  std::vector<double> cycles_;
  std::vector<std::vector<double>> values_;
  std::vector<Chart> charts_;
  std::vector<std::pair<QPointer<QDialog>, Chart>> windows_;
};

}  // namespace tessera::ui
