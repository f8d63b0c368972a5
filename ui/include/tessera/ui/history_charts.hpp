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

 private:
  struct Chart {
    QLineSeries* series;
    QValueAxis *x, *y;
  };
  QWidget* box_;
  QVBoxLayout* layout_;
  std::vector<std::string> labels_;
  std::vector<Chart> charts_;
};

}  // namespace tessera::ui
