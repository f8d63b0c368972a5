// History charts: rebuilt when the series change, points replaced on every snapshot.
#include "tessera/ui/history_charts.hpp"

#include <QChart>
#include <QChartView>
#include <QDialog>
#include <QEvent>
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
#include <cmath>
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

QString HistoryCharts::yTitle(int i) const {
  return charts_.at(static_cast<size_t>(i)).y->titleText();
}

QString HistoryCharts::axisTitle(int i) const {
  if (i < 0) return "cycle";
  const auto k = static_cast<size_t>(i);
  return k < titles_.size() ? QString::fromStdString(titles_[k]) : QString();
}

HistoryCharts::Chart HistoryCharts::makeChart(int yi, int xi) {
  Chart c;
  c.yi = yi, c.xi = xi;
  auto* chart = new QChart;
  c.series = new QLineSeries;
  chart->addSeries(c.series);
  c.x = new QValueAxis, c.y = new QValueAxis;
  c.x->setTitleText(axisTitle(xi));
  c.y->setTitleText(axisTitle(yi));
  c.x->setLabelFormat(xi < 0 ? "%.0f" : "%.4g");
  c.y->setLabelFormat("%.4g");
  chart->addAxis(c.x, Qt::AlignBottom);
  chart->addAxis(c.y, Qt::AlignLeft);
  c.series->attachAxis(c.x);
  c.series->attachAxis(c.y);
  const QString name = QString::fromStdString(labels_[static_cast<size_t>(yi)]);
  chart->setTitle(xi < 0 ? name
                         : name + " against " +
                               QString::fromStdString(labels_[static_cast<size_t>(xi)]));
  chart->legend()->hide();
  chart->setMargins(QMargins(2, 2, 2, 2));
  c.view = new QChartView(chart);
  c.view->setRenderHint(QPainter::Antialiasing);
  c.view->setMinimumHeight(170);
  // Right click: enlarge, plot against another history, export for a report or a spreadsheet.
  c.view->setContextMenuPolicy(Qt::CustomContextMenu);
  QChartView* view = c.view;
  connect(view, &QWidget::customContextMenuRequested, this, [this, view, yi, xi](QPoint at) {
    QMenu menu;
    QAction* large = xi < 0 ? menu.addAction("Enlarge") : nullptr;
    QMenu* against = menu.addMenu("Plot against");
    for (size_t j = 0; j < labels_.size(); ++j)
      if (static_cast<int>(j) != yi)
        against->addAction(QString::fromStdString(labels_[j]), this,
                           [this, yi, j] { plotAgainst(yi, static_cast<int>(j)); });
    QAction* save = menu.addAction("Export chart (PNG, SVG or CSV)…");
    QAction* chosen = menu.exec(view->mapToGlobal(at));
    // (snapshots arrive while the menu is open: the histories may have changed)
    if (static_cast<size_t>(yi) >= labels_.size()) return;
    if (chosen && chosen == large) enlarge(yi);
    if (!chosen || chosen != save) return;
    const QString path = QFileDialog::getSaveFileName(
        this, "Export chart", QString::fromStdString(labels_[size_t(yi)]) + ".png",
        "PNG image (*.png);;SVG drawing (*.svg);;CSV table (*.csv)");
    const Chart* shown = nullptr;
    for (const Chart& small : charts_)
      if (small.view == view) shown = &small;
    for (const auto& [window, big] : windows_)
      if (big.view == view) shown = &big;
    if (shown && !path.isEmpty() && !exportTo(*shown, path))
      QMessageBox::warning(this, "Tessera", "cannot write " + path);
  });
  return c;
}

void HistoryCharts::update(const Snapshot& s) {
  cycles_ = s.history_cycles, values_ = s.history_values;
  if (s.history_labels != labels_) {
    // New set of series: one chart each; the windows of the old ones close.
    while (QLayoutItem* item = layout_->takeAt(0)) {
      delete item->widget();
      delete item;
    }
    for (auto& [window, chart] : windows_)
      if (window) window->close();
    windows_.clear();
    charts_.clear();
    labels_ = s.history_labels;
    titles_ = s.history_titles;
    titles_.resize(labels_.size());
    for (size_t i = 0; i < labels_.size(); ++i) {
      charts_.push_back(makeChart(static_cast<int>(i), -1));
      charts_.back().view->viewport()->installEventFilter(this);
      layout_->addWidget(charts_.back().view);
    }
    if (labels_.empty())
      layout_->addWidget(new QLabel("No histories: add one with 'history QUANTITY'."));
    layout_->addStretch();
  }
  for (Chart& c : charts_) fill(c);
  std::erase_if(windows_, [](const auto& w) { return w.first.isNull(); });
  for (auto& [window, chart] : windows_) fill(chart);
}

void HistoryCharts::fill(Chart& c) {
  if (static_cast<size_t>(c.yi) >= values_.size()) return;
  const std::vector<double>& ys = values_[static_cast<size_t>(c.yi)];
  const std::vector<double>* xs =
      c.xi < 0 ? &cycles_
               : (static_cast<size_t>(c.xi) < values_.size() ? &values_[size_t(c.xi)] : nullptr);
  if (!xs) return;
  QList<QPointF> points;
  double x0 = 0, x1 = 0, lo = 0, hi = 0;
  bool any = false;
  for (size_t r = 0; r < ys.size() && r < xs->size(); ++r) {
    const double x = (*xs)[r], y = ys[r];
    if (!std::isfinite(x) || !std::isfinite(y)) continue;  // a deleted block's rows
    points.append(QPointF(x, y));
    x0 = any ? std::min(x0, x) : x, x1 = any ? std::max(x1, x) : x;
    lo = any ? std::min(lo, y) : y, hi = any ? std::max(hi, y) : y, any = true;
  }
  c.series->replace(points);
  // Axes around the curve: cycles from the first, values with a margin; no negative axis for a
  // quantity that never goes below zero (ratio, energy, time).
  const auto padded = [](double a, double b, double& from, double& to) {
    const double pad = b > a ? 0.05 * (b - a) : std::max(1e-12, 0.05 * std::abs(b));
    from = a >= 0 && a - pad < 0 ? 0.0 : a - pad, to = b + pad;
  };
  double ax0 = x0, ax1 = std::max(x1, x0 + 1.0), ay0 = 0, ay1 = 1;
  if (c.xi >= 0) padded(x0, x1, ax0, ax1);
  padded(lo, hi, ay0, ay1);
  // Ticks at round values (multiples of 1, 2 or 5 times a power of ten). Each axis goes back
  // to fixed ticks while its range changes: the old interval over a new, far wider range would
  // make millions of ticks.
  for (auto [axis, a, b] : {std::tuple{c.x, ax0, ax1}, std::tuple{c.y, ay0, ay1}}) {
    axis->setTickType(QValueAxis::TicksFixed);
    axis->setRange(a, b);
    const std::vector<double> ticks = round_ticks(a, b, 5);
    if (ticks.size() < 2 || !(ticks[1] - ticks[0] > 1e-9 * (std::abs(a) + std::abs(b)))) continue;
    axis->setTickAnchor(ticks[0]);
    axis->setTickInterval(ticks[1] - ticks[0]);
    axis->setTickType(QValueAxis::TicksDynamic);
  }
}

QDialog* HistoryCharts::openWindow(int yi, int xi) {
  if (yi < 0 || static_cast<size_t>(yi) >= labels_.size() || xi >= static_cast<int>(labels_.size()))
    return nullptr;
  Chart c = makeChart(yi, xi);
  auto* window = new QDialog(this);
  window->setAttribute(Qt::WA_DeleteOnClose);
  window->setWindowTitle(c.series->chart()->title());
  auto* layout = new QVBoxLayout(window);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(c.view);
  window->resize(900, 600);
  fill(c);
  windows_.emplace_back(window, c);
  window->show();
  return window;
}

QDialog* HistoryCharts::enlarge(int i) {
  return openWindow(i, -1);
}

QDialog* HistoryCharts::plotAgainst(int y, int x) {
  return x < 0 ? nullptr : openWindow(y, x);
}

int HistoryCharts::windowCount() const {
  return static_cast<int>(std::count_if(windows_.begin(), windows_.end(),
                                        [](const auto& w) { return !w.first.isNull(); }));
}

QList<QPointF> HistoryCharts::windowPoints(int k) const {
  int seen = 0;
  for (const auto& [window, chart] : windows_)
    if (window && seen++ == k) return chart.series->points();
  return {};
}

bool HistoryCharts::eventFilter(QObject* watched, QEvent* e) {
  // A double click on a small chart enlarges it.
  if (e->type() == QEvent::MouseButtonDblClick)
    for (const Chart& c : charts_)
      if (c.view->viewport() == watched) {
        enlarge(c.yi);
        return true;
      }
  return QScrollArea::eventFilter(watched, e);
}

bool HistoryCharts::exportChart(int i, const QString& path) const {
  if (i < 0 || static_cast<size_t>(i) >= charts_.size()) return false;
  return exportTo(charts_[static_cast<size_t>(i)], path);
}

bool HistoryCharts::exportTo(const Chart& c, const QString& path) const {
  const QString ext = QFileInfo(path).suffix().toLower();
  if (ext == "csv") {
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Text)) return false;
    QTextStream out(&f);
    const auto heading = [&](int i) {
      if (i < 0) return QString("cycle");
      const QString title = axisTitle(i), unit = title.section('[', 1).section(']', 0, 0);
      return QString::fromStdString(labels_[static_cast<size_t>(i)]) +
             (unit.isEmpty() ? "" : " [" + unit + "]");
    };
    out << heading(c.xi) << "," << heading(c.yi) << "\n";
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
