#include "ImagePane.h"

#include <QPainter>

#include <algorithm>

namespace vct::ui {

ImagePane::ImagePane(const QString& caption, QWidget* parent)
    : QWidget(parent)
    , m_caption(caption)
{
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void ImagePane::setImage(const QImage& image)
{
    m_image = image;
    update();
}

void ImagePane::setCaption(const QString& caption)
{
    m_caption = caption;
    update();
}

QSize ImagePane::sizeHint() const
{
    // Big enough to judge a comparison by eye: the panes were 128 px thumbnails in a narrow dock.
    return QSize(320, 240 + fontMetrics().height());
}

QSize ImagePane::minimumSizeHint() const
{
    return QSize(64, 48 + fontMetrics().height());
}

void ImagePane::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    const int textHeight = fontMetrics().height() + 2;
    const QRect area(0, 0, width(), std::max(1, height() - textHeight));
    painter.fillRect(area, palette().color(QPalette::Dark));
    if (!m_image.isNull()) {
        QSize size = m_image.size().scaled(area.size(), Qt::KeepAspectRatio);
        // Whole multiples when enlarging, so every source pixel is the same size on screen.
        const int factor = std::min(area.width() / m_image.width(), area.height() / m_image.height());
        if (factor >= 1)
            size = m_image.size() * factor;
        QRect target(QPoint(0, 0), size);
        target.moveCenter(area.center());
        painter.setRenderHint(QPainter::SmoothPixmapTransform, factor < 1);
        painter.drawImage(target, m_image);
    }
    painter.setPen(palette().color(QPalette::WindowText));
    painter.drawText(
        QRect(0, area.bottom() + 1, width(), textHeight), Qt::AlignHCenter | Qt::AlignVCenter, m_caption);
}

} // namespace vct::ui
