// History charts: rebuilt when the series change, points replaced on every snapshot.
#include "tessera/ui/history_charts.hpp"

#include <QChart>
#include <QChartView>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QGraphicsScene>
#include <QImage>
#include <QLabel>
#include <QLineSeries>
#include <QMenu>
#include <QMessageBox>
#include <QPainter>
#include <QSvgGenerator>
#include <QTextStream>
#include <QVBoxLayout>
#include <QValueAxis>
#include <algorithm>
#include <tuple>

#include "tessera/ui/colour_map.hpp"

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
      y->setLabelFormat("%.4g");
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
      // Right click: export the chart for a report or a spreadsheet.
      view->setContextMenuPolicy(Qt::CustomContextMenu);
      const int index = static_cast<int>(charts_.size());
      connect(view, &QWidget::customContextMenuRequested, this, [this, view, index](QPoint at) {
        QMenu menu;
        QAction* save = menu.addAction("Export chart (PNG, SVG or CSV)…");
        if (menu.exec(view->mapToGlobal(at)) != save) return;
        const QString path = QFileDialog::getSaveFileName(
            this, "Export chart", QString::fromStdString(labels_[size_t(index)]) + ".png",
            "PNG image (*.png);;SVG drawing (*.svg);;CSV table (*.csv)");
        if (!path.isEmpty() && !exportChart(index, path))
          QMessageBox::warning(this, "Tessera", "cannot write " + path);
      });
      layout_->addWidget(view);
      charts_.push_back({series, x, y, view});
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
    const double x0 = s.history_cycles.empty() ? 0.0 : s.history_cycles.front(),
                 x1 = s.history_cycles.empty() ? 1.0 : std::max(1.0, s.history_cycles.back());
    const double pad = hi > lo ? 0.05 * (hi - lo) : std::max(1e-12, 0.05 * std::abs(hi));
    // No negative axis for a quantity that never goes below zero (ratio, energy, time).
    const double y0 = lo >= 0 && lo - pad < 0 ? 0.0 : lo - pad, y1 = hi + pad;
    // Ticks at round values (multiples of 1, 2 or 5 times a power of ten). Each axis goes back
    // to fixed ticks while its range changes: the old interval over a new, far wider range
    // would make millions of ticks.
    for (auto [axis, a, b] : {std::tuple{charts_[i].x, x0, x1}, std::tuple{charts_[i].y, y0, y1}}) {
      axis->setTickType(QValueAxis::TicksFixed);
      axis->setRange(a, b);
      const std::vector<double> ticks = round_ticks(a, b, 5);
      if (ticks.size() < 2 || !(ticks[1] - ticks[0] > 1e-9 * (std::abs(a) + std::abs(b)))) continue;
      axis->setTickAnchor(ticks[0]);
      axis->setTickInterval(ticks[1] - ticks[0]);
      axis->setTickType(QValueAxis::TicksDynamic);
    }
  }
}

bool HistoryCharts::exportChart(int i, const QString& path) const {
  if (i < 0 || static_cast<size_t>(i) >= charts_.size()) return false;
  const Chart& c = charts_[static_cast<size_t>(i)];
  const QString ext = QFileInfo(path).suffix().toLower();
  if (ext == "csv") {
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Text)) return false;
    QTextStream out(&f);
    out << "cycle," << QString::fromStdString(labels_[static_cast<size_t>(i)]) << "\n";
    for (const QPointF& p : c.series->points())
      out << QString::number(p.x(), 'g', 12) << "," << QString::number(p.y(), 'g', 12) << "\n";
    return f.error() == QFile::NoError;
  }
  const QSize size(std::max(800, c.view->width()), std::max(500, c.view->height()));
  // The chart laid out at the export's size for the drawing, then given back its own.
  QChart* chart = c.series->chart();
  const auto render = [&](QPainter& p) {
    const QSizeF old = chart->size();
    chart->resize(size);
    chart->scene()->render(&p, QRectF(QPointF(0, 0), size), QRectF(chart->pos(), QSizeF(size)));
    chart->resize(old);
  };
  if (ext == "png") {
    QImage image(size, QImage::Format_ARGB32);
    image.fill(Qt::white);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    render(p);
    p.end();
    return image.save(path, "PNG");
  }
  if (ext == "svg") {
    QSvgGenerator svg;
    svg.setFileName(path);
    svg.setSize(size);
    svg.setViewBox(QRect(QPoint(0, 0), size));
    QPainter p;
    if (!p.begin(&svg)) return false;
    render(p);
    p.end();
    return QFileInfo(path).size() > 0;
  }
  return false;
}

}  // namespace tessera::ui
