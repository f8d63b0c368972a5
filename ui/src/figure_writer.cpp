// QPainter drawing of scenes and the PNG/SVG/PDF writers.
#include "tessera/ui/figure_writer.hpp"

#include <QFileInfo>
#include <QFontMetricsF>
#include <QImage>
#include <QPainter>
#include <QPainterPath>
#include <QPdfWriter>
#include <QSvgGenerator>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "depth_raster.hpp"
#include "tessera/core/model.hpp"
#include "tessera/script/script.hpp"

namespace tessera::ui {

namespace {
QColor qcolour(Rgb c) {
  return QColor(c.r, c.g, c.b);
}

QString number(double v) {
  return QString::number(v, 'g', 3);
}

// A round length near `target`: 1, 2 or 5 times a power of ten.
double nice_length(double target) {
  const double p = std::pow(10.0, std::floor(std::log10(target)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * p <= target) return m * p;
  return p;
}

// Colour bar or swatches in `box`; returns the height used.
double paint_legend(QPainter& p, const Legend& L, const QRectF& box, double font_px) {
  if (L.title.empty()) return 0;
  p.setPen(Qt::black);
  p.drawText(QRectF(box.left(), box.top(), box.width(), 1.4 * font_px), Qt::AlignLeft,
             QString::fromStdString(L.title));
  double y = box.top() + 1.6 * font_px;
  const double sw = 1.2 * font_px;
  if (L.continuous) {
    const double h = std::min(box.height() * 0.8, 12 * font_px);
    QLinearGradient g(0, y + h, 0, y);
    for (int i = 0; i <= 10; ++i) g.setColorAt(i / 10.0, qcolour(ramp(i / 10.0)));
    p.fillRect(QRectF(box.left(), y, sw, h), g);
    p.setPen(QPen(Qt::black, 0));
    p.drawRect(QRectF(box.left(), y, sw, h));
    // Labels at round values within the range.
    for (double v : round_ticks(L.lo, L.hi)) {
      const double ty = y + h - h * (L.hi > L.lo ? (v - L.lo) / (L.hi - L.lo) : 0.0);
      p.drawLine(QPointF(box.left() + sw, ty), QPointF(box.left() + sw * 1.3, ty));
      p.drawText(QPointF(box.left() + sw * 1.5, ty + 0.35 * font_px),
                 QString::fromStdString(tick_text(v)));
    }
    return y + h + font_px - box.top();
  }
  const size_t shown = std::min<size_t>(L.entries.size(), 12);
  for (size_t i = 0; i < shown; ++i) {
    p.fillRect(QRectF(box.left(), y, sw, 0.9 * font_px), qcolour(L.entries[i].second));
    p.setPen(QPen(Qt::black, 0));
    p.drawRect(QRectF(box.left(), y, sw, 0.9 * font_px));
    p.drawText(QPointF(box.left() + sw * 1.5, y + 0.85 * font_px),
               QString::fromStdString(L.entries[i].first));
    y += 1.3 * font_px;
  }
  if (L.entries.size() > shown)
    p.drawText(QPointF(box.left(), y + 0.85 * font_px),
               QString("and %1 more").arg(L.entries.size() - shown)),
        y += 1.3 * font_px;
  return y + font_px - box.top();
}
}  // namespace

void paint_scene(QPainter& p, const Scene& s, const QRectF& area) {
  p.save();
  p.setRenderHint(QPainter::Antialiasing);
  p.fillRect(area, Qt::white);
  const double font_px = std::clamp(area.height() / 45.0, 7.0, 28.0);
  QFont font = p.font();
  font.setPixelSize(static_cast<int>(std::lround(font_px)));
  p.setFont(font);
  // Layout: title above, legends to the right, scale bar and caption below.
  const double m = font_px;
  const QRectF title(area.left() + m, area.top() + 0.5 * m, area.width() - 2 * m, 1.6 * font_px);
  const double legend_w = std::min(area.width() * 0.22, 16 * font_px);
  // The caption's height as wrapped to the page width (at least two lines), below the scale bar.
  const QString caption = QString::fromStdString(s.caption);
  const QRectF caption_box(area.left() + m, 0, area.width() - 2 * m, 1e6);
  const double caption_h = std::max(
      2.2 * font_px, QFontMetricsF(font, p.device())
                         .boundingRect(caption_box, Qt::AlignLeft | Qt::TextWordWrap, caption)
                         .height());
  QRectF plot(area.left() + m, title.bottom() + 0.5 * m, area.width() - legend_w - 3 * m,
              area.height() - title.height() - 3.7 * m - caption_h);
  QFont bold = font;
  bold.setBold(true);
  p.setFont(bold);
  p.setPen(Qt::black);
  p.drawText(title, Qt::AlignHCenter | Qt::AlignVCenter, QString::fromStdString(s.title));
  p.setFont(font);
  // Model to page: equal scales, y up, centred in the plot box.
  const Vec2 span = s.hi - s.lo;
  const double k = std::min(plot.width() / span.x(), plot.height() / span.y());
  const QPointF c0 = plot.center();
  const Vec2 mid = 0.5 * (s.lo + s.hi);
  auto map = [&](const Vec2& v) {
    return QPointF(c0.x() + k * (v.x() - mid.x()), c0.y() - k * (v.y() - mid.y()));
  };
  p.save();
  p.setClipRect(plot);
  const QPen edge(QColor(60, 60, 60), std::max(0.5, font_px / 25.0));
  // Block fills, zones over them (a hairline in their own colour closes the seams), then the
  // block outlines on top.
  auto draw = [&](const std::vector<ScenePolygon>& list, bool fill, bool outline) {
    for (const auto& poly : list) {
      QPolygonF q;
      for (const Vec2& v : poly.points) q << map(v);
      p.setPen(outline && poly.outline ? edge
               : fill                  ? QPen(qcolour(poly.colour), 0)
                                       : QPen(Qt::NoPen));
      p.setBrush(fill ? QBrush(qcolour(poly.colour)) : QBrush(Qt::NoBrush));
      p.drawPolygon(q);
    }
  };
  if (s.three) {
    // 3D: faces, outlines and contacts through a depth buffer at twice the page's resolution
    // (smoothed down), drawn as one image; PNG is the format for 3D figures.
    constexpr double kOver = 2.0;
    const QSize size(static_cast<int>(std::ceil(plot.width() * kOver)),
                     static_cast<int>(std::ceil(plot.height() * kOver)));
    const QImage image = depth_raster(
        s, size, [&](const Vec2& v) { return (map(v) - plot.topLeft()) * kOver; },
        kOver * edge.widthF());
    p.drawImage(plot, image.scaled(static_cast<int>(std::ceil(plot.width())),
                                   static_cast<int>(std::ceil(plot.height())),
                                   Qt::IgnoreAspectRatio, Qt::SmoothTransformation));
  } else {
    draw(s.polygons, true, s.zones.empty());
    if (!s.zones.empty()) {
      draw(s.zones, true, false);
      draw(s.polygons, false, true);
    }
    p.setPen(Qt::NoPen);
    for (const auto& bar : s.bars) {
      QPolygonF q;
      for (const Vec2& v : bar.corners) q << map(v);
      p.setBrush(qcolour(bar.colour));
      p.drawPolygon(q);
    }
  }
  p.setPen(QPen(Qt::black, std::max(0.8, font_px / 12.0)));
  for (const auto& a : s.arrows) {
    const QPointF t = map(a.tail), h = map(a.head);
    p.drawLine(t, h);
    const QPointF d = h - t;
    const double len = std::hypot(d.x(), d.y());
    if (len <= 0) continue;
    const QPointF u = d / len, n(-u.y(), u.x());
    const double hs = std::min(0.3 * len, 0.6 * font_px);
    p.drawLine(h, h - hs * u + 0.5 * hs * n);
    p.drawLine(h, h - hs * u - 0.5 * hs * n);
  }
  p.restore();
  // Legends.
  const QRectF legend_box(plot.right() + m, plot.top(), legend_w, plot.height());
  const double used = paint_legend(p, s.blocks_legend, legend_box, font_px);
  const double more =
      paint_legend(p, s.contacts_legend, legend_box.adjusted(0, used, 0, 0), font_px);
  if (!s.support_legend.title.empty())
    paint_legend(p, s.support_legend, legend_box.adjusted(0, used + more, 0, 0), font_px);
  // Scale bar: a round length near a fifth of the plot width (none in perspective).
  const double len = nice_length(plot.width() / k / 5.0);
  const QPointF sb(plot.left(), plot.bottom() + 1.5 * m);
  p.setPen(QPen(Qt::black, std::max(1.0, font_px / 8.0)));
  if (!s.perspective) {
    p.drawLine(sb, sb + QPointF(k * len, 0));
    p.drawLine(sb + QPointF(0, -0.3 * m), sb + QPointF(0, 0.3 * m));
    p.drawLine(sb + QPointF(k * len, -0.3 * m), sb + QPointF(k * len, 0.3 * m));
    p.drawText(sb + QPointF(k * len + 0.5 * m, 0.35 * font_px), number(len) + " m");
  }
  p.drawText(QRectF(area.left() + m, plot.bottom() + 2.3 * m, area.width() - 2 * m, caption_h),
             Qt::AlignLeft | Qt::TextWordWrap, caption);
  p.restore();
}

void write_figure(const Scene& s, const std::string& path, int width, int height) {
  const QString file = QString::fromStdString(path);
  const QString ext = QFileInfo(file).suffix().toLower();
  const QRectF area(0, 0, width, height);
  if (ext == "png") {
    QImage image(width, height, QImage::Format_ARGB32);
    image.fill(Qt::white);
    {
      QPainter p(&image);
      paint_scene(p, s, area);
    }
    if (!image.save(file, "PNG")) throw std::runtime_error("cannot write '" + path + "'");
  } else if (ext == "svg") {
    QSvgGenerator svg;
    svg.setFileName(file);
    svg.setSize(QSize(width, height));
    svg.setViewBox(area);
    svg.setResolution(96);  // CSS pixels: browsers show the figure at width x height
    svg.setTitle(QString::fromStdString(s.title));
    svg.setDescription("Tessera figure");
    QPainter p;
    if (!p.begin(&svg)) throw std::runtime_error("cannot write '" + path + "'");
    paint_scene(p, s, area);
    p.end();
  } else if (ext == "pdf") {
    QPdfWriter pdf(file);
    pdf.setResolution(72);
    pdf.setPageSize(QPageSize(QSizeF(width, height), QPageSize::Point));
    pdf.setPageMargins(QMarginsF(0, 0, 0, 0));
    pdf.setTitle(QString::fromStdString(s.title));
    pdf.setCreator("Tessera");
    QPainter p;
    if (!p.begin(&pdf)) throw std::runtime_error("cannot write '" + path + "'");
    paint_scene(p, s, area);
    p.end();
  } else {
    throw std::runtime_error("'" + path + "': a figure is written as .png, .svg or .pdf");
  }
  if (!QFileInfo(file).exists() || QFileInfo(file).size() == 0)
    throw std::runtime_error("cannot write '" + path + "'");
}

FigureSink figure_sink() {
  return [](const FigureRequest& r, const Model& m) {
    const Snapshot snap = make_snapshot(m, r.view.title, {});
    write_figure(build_scene(snap, r.view), r.path, r.width, r.height);
  };
}

}  // namespace tessera::ui
