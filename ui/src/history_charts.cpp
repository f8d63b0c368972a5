// History charts: rebuilt when the series change, points replaced on every snapshot.
#include "tessera/ui/history_charts.hpp"

#include <QChart>
#include <QChartView>
#include <QLabel>
#include <QLineSeries>
#include <QVBoxLayout>
#include <QValueAxis>
#include <algorithm>

namespace tessera::ui {

HistoryCharts::HistoryCharts(QWidget* parent)
    : QScrollArea(parent), box_(new QWidget), layout_(new QVBoxLayout(box_)) {
  setWidget(box_);
  setWidgetResizable(true);
  layout_->addWidget(new QLabel("No histories: add one with 'history QUANTITY' in the script."));
  layout_->addStretch();
}

int HistoryCharts::pointCount(int i) const {
  return static_cast<int>(charts_.at(static_cast<size_t>(i)).series->count());
}

void HistoryCharts::update(const Snapshot& s) {
  if (s.history_labels != labels_) {
    // New set of series: one chart each.
    while (QLayoutItem* item = layout_->takeAt(0)) {
      delete item->widget();
      delete item;
    }
    charts_.clear();
    labels_ = s.history_labels;
    for (const std::string& label : labels_) {
      auto* chart = new QChart;
      auto* series = new QLineSeries;
      series->setName(QString::fromStdString(label));
      chart->addSeries(series);
      auto *x = new QValueAxis, *y = new QValueAxis;
      x->setTitleText("cycle");
      x->setLabelFormat("%.0f");
      y->setLabelFormat("%.3g");
      chart->addAxis(x, Qt::AlignBottom);
      chart->addAxis(y, Qt::AlignLeft);
      series->attachAxis(x);
      series->attachAxis(y);
      chart->setTitle(QString::fromStdString(label));
      chart->legend()->hide();
      chart->setMargins(QMargins(2, 2, 2, 2));
      auto* view = new QChartView(chart);
      view->setRenderHint(QPainter::Antialiasing);
      view->setMinimumHeight(170);
      layout_->addWidget(view);
      charts_.push_back({series, x, y});
    }
    if (labels_.empty())
      layout_->addWidget(new QLabel("No histories: add one with 'history QUANTITY'."));
    layout_->addStretch();
  }
  for (size_t i = 0; i < charts_.size() && i < s.history_values.size(); ++i) {
    QList<QPointF> points;
    const auto& v = s.history_values[i];
    double lo = 0, hi = 0;
    for (size_t r = 0; r < v.size(); ++r) {
      points.append(QPointF(s.history_cycles[r], v[r]));
      lo = r ? std::min(lo, v[r]) : v[r], hi = r ? std::max(hi, v[r]) : v[r];
    }
    charts_[i].series->replace(points);
    const double x1 = s.history_cycles.empty() ? 1.0 : std::max(1.0, s.history_cycles.back());
    charts_[i].x->setRange(s.history_cycles.empty() ? 0.0 : s.history_cycles.front(), x1);
    const double pad = hi > lo ? 0.05 * (hi - lo) : std::max(1e-12, 0.05 * std::abs(hi));
    // No negative axis for a quantity that never goes below zero (ratio, energy, time).
    charts_[i].y->setRange(lo >= 0 && lo - pad < 0 ? 0.0 : lo - pad, hi + pad);
  }
}

}  // namespace tessera::ui
