#pragma once

#include "plot/Chart.h"

#include <QImage>
#include <QSize>
#include <QString>

namespace vct::plot {

/**
 * Writes a Chart as SVG (hand-written text) and as PNG (QPainter on a QImage), both from ChartPainter so
 * they show the same thing. SVG needs only QtCore; PNG needs a QGuiApplication for its fonts; a headless
 * tool can create one on the "offscreen" platform (see ChartWriter::canDrawText).
 */
class ChartWriter {
public:
    static QString toSvg(const Chart& chart, QSize size);
    /** A null image when text cannot be drawn (no QGuiApplication). */
    static QImage toImage(const Chart& chart, QSize size);
    /** Whether a QGuiApplication exists, which QPainter text needs. */
    static bool canDrawText();

    /** Each returns false and sets *error (when given) on failure; files are replaced atomically. */
    static bool writeSvg(const Chart& chart, const QString& path, QSize size, QString* error = nullptr);
    static bool writePng(const Chart& chart, const QString& path, QSize size, QString* error = nullptr);
    /** Writes `basePath`.svg and `basePath`.png. */
    static bool write(const Chart& chart, const QString& basePath, QSize size, QString* error = nullptr);
};

} // namespace vct::plot
