#pragma once

#include <QColor>
#include <QPointF>
#include <QRectF>
#include <QString>

#include <vector>

namespace vct::plot {

enum class MarkerShape { Circle, Square, Triangle, Diamond };
enum class TextAnchor { Start, Middle, End };

/**
 * What ChartPainter draws with, so one layout feeds both the SVG text and the QPainter image. Coordinates
 * are pixels, origin top left. `role` names what a primitive is ("marker", "highlight", "point-label", ...):
 * the SVG writes it as the element's class, so tests and style sheets can find things; QPainter ignores it.
 */
class ChartCanvas {
public:
    virtual ~ChartCanvas() = default;
    virtual void rect(const QRectF& r, const QColor& fill, const QColor& stroke, const char* role) = 0;
    virtual void line(QPointF a, QPointF b, const QColor& color, double width, const char* role) = 0;
    virtual void polyline(
        const std::vector<QPointF>& points, const QColor& color, double width, bool dashed, const char* role)
        = 0;
    virtual void marker(QPointF center, double radius, MarkerShape shape, const QColor& fill,
        const QColor& stroke, const char* role)
        = 0;
    /** `baseline` is the text's anchor point on its baseline; `rotationDeg` turns it clockwise about that
     * point. */
    virtual void text(QPointF baseline, const QString& text, double pixelSize, TextAnchor anchor,
        const QColor& color, const char* role, double rotationDeg = 0.0, bool bold = false)
        = 0;
    /** Width in pixels the text takes at this size (an estimate where no fonts are at hand). */
    virtual double textWidth(const QString& text, double pixelSize, bool bold = false) const = 0;
};

} // namespace vct::plot
