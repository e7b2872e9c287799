#pragma once

#include "plot/ChartCanvas.h"

class QPainter;

namespace vct::plot {

/**
 * Draws through a QPainter (on a QImage for PNG files). Text needs the font database, so a QGuiApplication
 * must exist (the offscreen platform is enough).
 */
class PainterCanvas final : public ChartCanvas {
public:
    explicit PainterCanvas(QPainter& painter);

    void rect(const QRectF& r, const QColor& fill, const QColor& stroke, const char* role) override;
    void line(QPointF a, QPointF b, const QColor& color, double width, const char* role) override;
    void polyline(const std::vector<QPointF>& points, const QColor& color, double width, bool dashed,
        const char* role) override;
    void marker(QPointF center, double radius, MarkerShape shape, const QColor& fill, const QColor& stroke,
        const char* role) override;
    void text(QPointF baseline, const QString& text, double pixelSize, TextAnchor anchor, const QColor& color,
        const char* role, double rotationDeg = 0.0, bool bold = false) override;
    double textWidth(const QString& text, double pixelSize, bool bold = false) const override;

private:
    QPainter& m_painter;
};

} // namespace vct::plot
