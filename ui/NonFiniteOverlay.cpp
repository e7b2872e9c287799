#include "NonFiniteOverlay.h"

namespace vct::ui {

NonFiniteOverlay::NonFiniteOverlay(QWidget* parent)
    : QLabel(parent)
{
    setObjectName(QStringLiteral("nonFiniteOverlay"));
    setAttribute(Qt::WA_TransparentForMouseEvents); // the camera keeps its clicks
    setMargin(6);
    hide();
}

void NonFiniteOverlay::showCounts(const std::vector<render::NonFiniteCount>& counts)
{
    m_total = 0;
    m_checked = int(counts.size());
    QStringList offenders;
    for (const render::NonFiniteCount& c : counts) {
        m_total += c.count;
        if (c.count)
            offenders << tr("%1: %2").arg(QString::fromStdString(c.resource)).arg(c.count);
    }
    QString text = m_total
        ? tr("NaN/Inf: %1 texels").arg(m_total) + QLatin1Char('\n') + offenders.join(QLatin1Char('\n'))
        : tr("NaN/Inf: none in %1 targets and voxel levels").arg(m_checked);
    setText(text);
    setStyleSheet(m_total ? QStringLiteral("background: rgba(160,0,0,200); color: white;")
                          : QStringLiteral("background: rgba(0,0,0,150); color: #9f9;"));
    adjustSize();
    move(8, 8);
    show();
}

} // namespace vct::ui
