// Paints a scene with QPainter: PNG, SVG and PDF figures for reports, from the window and from
// headless runs alike (no OpenGL needed).
#pragma once

#include <QRectF>
#include <string>

#include "tessera/io/figure.hpp"
#include "tessera/ui/scene.hpp"

class QPainter;

namespace tessera::ui {

// Draws the scene into `area`: title, model, legends, scale bar and caption.
void paint_scene(QPainter& p, const Scene& s, const QRectF& area);
// Writes a figure of width x height pixels (PNG) or points (SVG, PDF), by the path's extension.
// Throws std::runtime_error if the file cannot be written.
void write_figure(const Scene& s, const std::string& path, int width, int height);
// The renderer a script's `figure` command hands its requests to.
FigureSink figure_sink();

}  // namespace tessera::ui
