// Live history charts (Qt Charts): one small chart per history series against cycles.
#pragma once

#include <QScrollArea>
#include <vector>

#include "tessera/ui/snapshot.hpp"

class QChart;
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
  // Writes chart i to `path`: .png (its size on screen, at least 800 x 500), .svg, or .csv (the
  // cycles and values shown). Each chart's right-click menu offers these. False if it cannot.
  bool exportChart(int i, const QString& path) const;

 private:
  struct Chart {
    QLineSeries* series;
    QValueAxis *x, *y;
    QWidget* view;
  };
  QWidget* box_;
  QVBoxLayout* layout_;
  std::vector<std::string> labels_;
  std::vector<Chart> charts_;
};

}  // namespace tessera::ui
