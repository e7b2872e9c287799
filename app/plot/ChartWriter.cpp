#include "plot/ChartWriter.h"

#include "files/AtomicFile.h"
#include "plot/ChartPainter.h"
#include "plot/PainterCanvas.h"
#include "plot/SvgCanvas.h"

#include <QBuffer>
#include <QGuiApplication>
#include <QPainter>

namespace vct::plot {

namespace {

bool save(const QString& path, const QByteArray& bytes, QString* error)
{
    return files::AtomicFile::write(path, bytes, error);
}

} // namespace

QString ChartWriter::toSvg(const Chart& chart, QSize size)
{
    SvgCanvas canvas(size);
    ChartPainter::paint(chart, canvas, QSizeF(size));
    return canvas.document();
}

bool ChartWriter::canDrawText()
{
    return qobject_cast<QGuiApplication*>(QCoreApplication::instance()) != nullptr;
}

QImage ChartWriter::toImage(const Chart& chart, QSize size)
{
    if (!canDrawText() || size.isEmpty())
        return {};
    QImage image(size, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    PainterCanvas canvas(painter);
    ChartPainter::paint(chart, canvas, QSizeF(size));
    painter.end();
    return image;
}

bool ChartWriter::writeSvg(const Chart& chart, const QString& path, QSize size, QString* error)
{
    return save(path, toSvg(chart, size).toUtf8(), error);
}

bool ChartWriter::writePng(const Chart& chart, const QString& path, QSize size, QString* error)
{
    const QImage image = toImage(chart, size);
    if (image.isNull()) {
        if (error)
            *error = QStringLiteral(
                "cannot draw '%1': PNG charts need a QGuiApplication (QT_QPA_PLATFORM=offscreen will do)")
                         .arg(path);
        return false;
    }
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    if (!image.save(&buffer, "PNG")) {
        if (error)
            *error = QStringLiteral("cannot encode '%1' as PNG").arg(path);
        return false;
    }
    return save(path, bytes, error);
}

bool ChartWriter::write(const Chart& chart, const QString& basePath, QSize size, QString* error)
{
    return writeSvg(chart, basePath + QStringLiteral(".svg"), size, error)
        && writePng(chart, basePath + QStringLiteral(".png"), size, error);
}

} // namespace vct::plot
