#include "plot/SvgCanvas.h"

namespace vct::plot {

namespace {

QString number(double v)
{
    return QString::number(v, 'f', 2);
}

QString paint(const QColor& color)
{
    if (!color.isValid() || color.alpha() == 0)
        return QStringLiteral("none");
    return color.name(QColor::HexRgb);
}

QString opacity(const char* attribute, const QColor& color)
{
    if (!color.isValid() || color.alpha() == 255 || color.alpha() == 0)
        return {};
    return QStringLiteral(" %1=\"%2\"")
        .arg(QLatin1String(attribute), QString::number(color.alphaF(), 'f', 3));
}

QString escaped(const QString& text)
{
    return text.toHtmlEscaped(); // & < > " ; apostrophes never appear inside our double-quoted attributes
}

QString points(const std::vector<QPointF>& list)
{
    QString out;
    for (const QPointF& p : list) {
        if (!out.isEmpty())
            out += QLatin1Char(' ');
        out += number(p.x()) + QLatin1Char(',') + number(p.y());
    }
    return out;
}

} // namespace

SvgCanvas::SvgCanvas(QSize size)
    : m_size(size)
{
}

void SvgCanvas::rect(const QRectF& r, const QColor& fill, const QColor& stroke, const char* role)
{
    m_body += QStringLiteral(
        "<rect class=\"%1\" x=\"%2\" y=\"%3\" width=\"%4\" height=\"%5\" fill=\"%6\"%7 stroke=\"%8\"/>\n")
                  .arg(QLatin1String(role), number(r.x()), number(r.y()), number(r.width()),
                      number(r.height()), paint(fill), opacity("fill-opacity", fill), paint(stroke));
}

void SvgCanvas::line(QPointF a, QPointF b, const QColor& color, double width, const char* role)
{
    m_body += QStringLiteral(
        "<line class=\"%1\" x1=\"%2\" y1=\"%3\" x2=\"%4\" y2=\"%5\" stroke=\"%6\"%7 stroke-width=\"%8\"/>\n")
                  .arg(QLatin1String(role), number(a.x()), number(a.y()), number(b.x()), number(b.y()),
                      paint(color), opacity("stroke-opacity", color), number(width));
}

void SvgCanvas::polyline(
    const std::vector<QPointF>& list, const QColor& color, double width, bool dashed, const char* role)
{
    if (list.size() < 2)
        return;
    m_body += QStringLiteral(
        "<polyline class=\"%1\" points=\"%2\" fill=\"none\" stroke=\"%3\" stroke-width=\"%4\" "
        "stroke-linejoin=\"round\"%5/>\n")
                  .arg(QLatin1String(role), points(list), paint(color), number(width),
                      dashed ? QStringLiteral(" stroke-dasharray=\"7 4\"") : QString());
}

void SvgCanvas::marker(
    QPointF c, double radius, MarkerShape shape, const QColor& fill, const QColor& stroke, const char* role)
{
    const QString style
        = QStringLiteral("fill=\"%1\" stroke=\"%2\" stroke-width=\"1.2\"").arg(paint(fill), paint(stroke));
    const QString cls = QLatin1String(role);
    switch (shape) {
    case MarkerShape::Circle:
        m_body += QStringLiteral("<circle class=\"%1\" cx=\"%2\" cy=\"%3\" r=\"%4\" %5/>\n")
                      .arg(cls, number(c.x()), number(c.y()), number(radius), style);
        return;
    case MarkerShape::Square: {
        const double half = radius * 0.9;
        m_body += QStringLiteral("<rect class=\"%1\" x=\"%2\" y=\"%3\" width=\"%4\" height=\"%4\" %5/>\n")
                      .arg(cls, number(c.x() - half), number(c.y() - half), number(2.0 * half), style);
        return;
    }
    case MarkerShape::Triangle:
        m_body += QStringLiteral("<polygon class=\"%1\" points=\"%2\" %3/>\n")
                      .arg(cls,
                          points({ { c.x(), c.y() - 1.2 * radius },
                              { c.x() + 1.05 * radius, c.y() + 0.7 * radius },
                              { c.x() - 1.05 * radius, c.y() + 0.7 * radius } }),
                          style);
        return;
    case MarkerShape::Diamond:
        m_body += QStringLiteral("<polygon class=\"%1\" points=\"%2\" %3/>\n")
                      .arg(cls,
                          points({ { c.x(), c.y() - 1.25 * radius }, { c.x() + 1.25 * radius, c.y() },
                              { c.x(), c.y() + 1.25 * radius }, { c.x() - 1.25 * radius, c.y() } }),
                          style);
        return;
    }
}

void SvgCanvas::text(QPointF baseline, const QString& text, double pixelSize, TextAnchor anchor,
    const QColor& color, const char* role, double rotationDeg, bool bold)
{
    const char* anchorName = anchor == TextAnchor::Start ? "start"
        : anchor == TextAnchor::Middle                   ? "middle"
                                                         : "end";
    QString extra;
    if (rotationDeg != 0.0)
        extra += QStringLiteral(" transform=\"rotate(%1 %2 %3)\"")
                     .arg(number(rotationDeg), number(baseline.x()), number(baseline.y()));
    if (bold)
        extra += QStringLiteral(" font-weight=\"bold\"");
    m_body += QStringLiteral(
        "<text class=\"%1\" x=\"%2\" y=\"%3\" font-size=\"%4\" text-anchor=\"%5\" fill=\"%6\"%7>%8</text>\n")
                  .arg(QLatin1String(role), number(baseline.x()), number(baseline.y()), number(pixelSize),
                      QLatin1String(anchorName), paint(color), extra, escaped(text));
}

double SvgCanvas::textWidth(const QString& text, double pixelSize, bool bold) const
{
    return double(text.size()) * pixelSize * (bold ? 0.63 : 0.58);
}

QString SvgCanvas::document() const
{
    return QStringLiteral(
               "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
               "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"%1\" height=\"%2\" "
               "viewBox=\"0 0 %1 %2\" font-family=\"DejaVu Sans, Verdana, Arial, sans-serif\">\n")
               .arg(m_size.width())
               .arg(m_size.height())
        + m_body + QStringLiteral("</svg>\n");
}

} // namespace vct::plot
