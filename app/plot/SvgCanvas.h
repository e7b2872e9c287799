#pragma once

#include "plot/ChartCanvas.h"

#include <QSize>
#include <QString>

namespace vct::plot {

/**
 * Writes SVG 1.1 text by hand: no Qt SVG module needed, and the output stays small and diffable. Needs no
 * QGuiApplication; text widths are estimated from the font size (DejaVu Sans averages about 0.58 em).
 */
class SvgCanvas final : public ChartCanvas {
public:
    explicit SvgCanvas(QSize size);

    void rect(const QRectF& r, const QColor& fill, const QColor& stroke, const char* role) override;
    void line(QPointF a, QPointF b, const QColor& color, double width, const char* role) override;
    void polyline(const std::vector<QPointF>& points, const QColor& color, double width, bool dashed,
        const char* role) override;
    void marker(QPointF center, double radius, MarkerShape shape, const QColor& fill, const QColor& stroke,
        const char* role) override;
    void text(QPointF baseline, const QString& text, double pixelSize, TextAnchor anchor, const QColor& color,
        const char* role, double rotationDeg = 0.0, bool bold = false) override;
    double textWidth(const QString& text, double pixelSize, bool bold = false) const override;

    /** The complete document: XML declaration, <svg> root and everything drawn so far. */
    QString document() const;

private:
    QSize m_size;
    QString m_body;
};

} // namespace vct::plot
