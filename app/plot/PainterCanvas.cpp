#include "plot/PainterCanvas.h"

#include <QFont>
#include <QFontMetricsF>
#include <QPainter>
#include <QPolygonF>

#include <algorithm>
#include <cmath>

namespace vct::plot {

namespace {

QFont fontOf(double pixelSize, bool bold)
{
    QFont font(QStringLiteral("DejaVu Sans"));
    font.setPixelSize(std::max(1, int(std::lround(pixelSize))));
    font.setBold(bold);
    return font;
}

QBrush brushOf(const QColor& color)
{
    return color.isValid() ? QBrush(color) : QBrush(Qt::NoBrush);
}

QPen penOf(const QColor& color, double width)
{
    return color.isValid() ? QPen(color, width) : QPen(Qt::NoPen);
}

} // namespace

PainterCanvas::PainterCanvas(QPainter& painter)
    : m_painter(painter)
{
    m_painter.setRenderHint(QPainter::Antialiasing);
    m_painter.setRenderHint(QPainter::TextAntialiasing);
}

void PainterCanvas::rect(const QRectF& r, const QColor& fill, const QColor& stroke, const char*)
{
    m_painter.setPen(penOf(stroke, 1.0));
    m_painter.setBrush(brushOf(fill));
    m_painter.drawRect(r);
}

void PainterCanvas::line(QPointF a, QPointF b, const QColor& color, double width, const char*)
{
    m_painter.setPen(penOf(color, width));
    m_painter.drawLine(a, b);
}

void PainterCanvas::polyline(
    const std::vector<QPointF>& points, const QColor& color, double width, bool dashed, const char*)
{
    if (points.size() < 2)
        return;
    QPen pen = penOf(color, width);
    pen.setJoinStyle(Qt::RoundJoin);
    if (dashed)
        pen.setDashPattern({ 7.0 / width, 4.0 / width }); // in pen widths; matches the SVG's 7 4 pixels
    m_painter.setPen(pen);
    m_painter.setBrush(Qt::NoBrush);
    m_painter.drawPolyline(points.data(), int(points.size()));
}

void PainterCanvas::marker(
    QPointF c, double radius, MarkerShape shape, const QColor& fill, const QColor& stroke, const char*)
{
    m_painter.setPen(penOf(stroke, 1.2));
    m_painter.setBrush(brushOf(fill));
    switch (shape) {
    case MarkerShape::Circle:
        m_painter.drawEllipse(c, radius, radius);
        return;
    case MarkerShape::Square: {
        const double half = radius * 0.9;
        m_painter.drawRect(QRectF(c.x() - half, c.y() - half, 2.0 * half, 2.0 * half));
        return;
    }
    case MarkerShape::Triangle:
        m_painter.drawPolygon(
            QPolygonF({ { c.x(), c.y() - 1.2 * radius }, { c.x() + 1.05 * radius, c.y() + 0.7 * radius },
                { c.x() - 1.05 * radius, c.y() + 0.7 * radius } }));
        return;
    case MarkerShape::Diamond:
        m_painter.drawPolygon(QPolygonF({ { c.x(), c.y() - 1.25 * radius }, { c.x() + 1.25 * radius, c.y() },
            { c.x(), c.y() + 1.25 * radius }, { c.x() - 1.25 * radius, c.y() } }));
        return;
    }
}

void PainterCanvas::text(QPointF baseline, const QString& text, double pixelSize, TextAnchor anchor,
    const QColor& color, const char*, double rotationDeg, bool bold)
{
    const QFont font = fontOf(pixelSize, bold);
    const double width = QFontMetricsF(font).horizontalAdvance(text);
    const double shift = anchor == TextAnchor::Start ? 0.0
        : anchor == TextAnchor::Middle               ? -0.5 * width
                                                     : -width;
    m_painter.save();
    m_painter.setFont(font);
    m_painter.setPen(color);
    m_painter.translate(baseline);
    m_painter.rotate(rotationDeg);
    m_painter.drawText(QPointF(shift, 0.0), text);
    m_painter.restore();
}

double PainterCanvas::textWidth(const QString& text, double pixelSize, bool bold) const
{
    return QFontMetricsF(fontOf(pixelSize, bold)).horizontalAdvance(text);
}

} // namespace vct::plot
