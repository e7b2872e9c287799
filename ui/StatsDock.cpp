#include "StatsDock.h"

#include "core/FrameStats.h"

#include <algorithm>

#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace vct::ui {

namespace {

enum Column { PassColumn, ActionColumn, ReasonColumn, GpuColumn, ColumnCount };
constexpr int kVisibleRows = 12; ///< rows the pass table shows without scrolling

QTableWidgetItem* makeItem(const QString& text, Qt::Alignment alignment = Qt::AlignLeft | Qt::AlignVCenter)
{
    auto* item = new QTableWidgetItem(text);
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    item->setTextAlignment(alignment);
    item->setToolTip(text);
    return item;
}

QLabel* makeValueLabel(const QString& objectName)
{
    auto* label = new QLabel(QStringLiteral("—"));
    label->setObjectName(objectName);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

} // namespace

StatsDock::StatsDock(QWidget* parent)
    : QDockWidget(tr("Render plan & stats"), parent)
{
    setObjectName(QStringLiteral("StatsDock"));
    auto* body = new QWidget(this);

    m_table = new QTableWidget(0, ColumnCount, body);
    m_table->setObjectName(QStringLiteral("passTable"));
    m_table->setHorizontalHeaderLabels({ tr("Pass"), tr("Action"), tr("Reason"), tr("GPU (ms)") });
    m_table->horizontalHeaderItem(ActionColumn)->setToolTip(tr("run, reused (inputs unchanged) or skipped"));
    m_table->horizontalHeaderItem(GpuColumn)->setToolTip(
        tr("GPU time from timer queries, of the frame before this one in the viewport (reading this frame's "
           "would "
           "stall it); — where the pass did not run then"));
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 4);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setAlternatingRowColors(true);
    // Reasons wrap rather than being cut at the panel's edge, and the table shows every pass of a frame
    // without scrolling (the pipeline has about a dozen).
    m_table->setWordWrap(true);
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->setMinimumHeight(m_table->horizontalHeader()->sizeHint().height()
        + kVisibleRows * (m_table->fontMetrics().height() + 4) + 2 * m_table->frameWidth());
    QHeaderView* header = m_table->horizontalHeader();
    header->setSectionResizeMode(PassColumn, QHeaderView::ResizeToContents);
    header->setSectionResizeMode(ActionColumn, QHeaderView::ResizeToContents);
    header->setSectionResizeMode(ReasonColumn, QHeaderView::Stretch);
    header->setSectionResizeMode(GpuColumn, QHeaderView::ResizeToContents);

    m_total = makeValueLabel(QStringLiteral("totalGpuLabel"));
    m_memory = makeValueLabel(QStringLiteral("voxelMemoryLabel"));
    m_memoryPerVoxel = makeValueLabel(QStringLiteral("voxelMemoryPerVoxelLabel"));
    m_memoryPerVoxel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred); // never widens the dock
    m_grid = makeValueLabel(QStringLiteral("voxelGridLabel"));
    m_frame = makeValueLabel(QStringLiteral("frameSizeLabel"));
    m_bounces = makeValueLabel(QStringLiteral("bouncesLabel"));
    // Its text changes every frame while the light converges: it must not widen the dock and move the view.
    m_bounces->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_bounces->setToolTip(
        tr("The bounce iteration: iterations for the current light, and the relative change of "
           "the voxels' radiance in the last one. While idle the view keeps iterating until the "
           "change is under the tolerance (Render settings: Bounces)."));
    auto* form = new QFormLayout;
    form->setContentsMargins(0, 0, 0, 0);
    form->addRow(tr("GPU total"), m_total);
    form->addRow(tr("Voxel memory"), m_memory);
    form->addRow(QString(), m_memoryPerVoxel);
    form->addRow(tr("Voxel grid"), m_grid);
    form->addRow(tr("Frame"), m_frame);
    form->addRow(tr("Bounces"), m_bounces);

    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(form);
    layout->addWidget(m_table);
    setWidget(body);
}

void StatsDock::showStats(const render::FrameStats& stats)
{
    // Updating in place instead of clearing avoids re-creating every item (and flicker) at frame rate.
    m_table->setRowCount(int(stats.passes.size()));
    for (int row = 0; row < int(stats.passes.size()); ++row) {
        const render::PassStats& pass = stats.passes[std::size_t(row)];
        const bool ran = pass.action == "run";
        // With the frame before's times a pass may have run then and not now, or the other way round.
        const bool timed = stats.timesFromPreviousFrame ? pass.gpuMs > 0.0 : ran;
        const QString cells[ColumnCount] = { QString::fromStdString(pass.name),
            QString::fromStdString(pass.action), QString::fromStdString(pass.reason),
            timed ? QString::number(pass.gpuMs, 'f', 3) : QStringLiteral("—") };
        for (int column = 0; column < ColumnCount; ++column) {
            QTableWidgetItem* item = m_table->item(row, column);
            if (!item) {
                const Qt::Alignment alignment = column == GpuColumn ? Qt::AlignRight | Qt::AlignVCenter
                                                                    : Qt::AlignLeft | Qt::AlignVCenter;
                m_table->setItem(row, column, makeItem(cells[column], alignment));
            } else if (item->text() != cells[column]) {
                item->setText(cells[column]);
                item->setToolTip(cells[column]);
            }
            // Passes that did no work this frame read as greyed out, as in profilers.
            m_table->item(row, column)
                ->setForeground(ran ? palette().brush(QPalette::Text)
                                    : palette().brush(QPalette::Disabled, QPalette::Text));
        }
    }

    m_total->setText(tr("%1 ms").arg(stats.totalGpuMs, 0, 'f', 3));
    m_memory->setText(tr("%1 MiB").arg(double(stats.voxelBytes) / (1024.0 * 1024.0), 0, 'f', 1));
    m_memoryPerVoxel->setText(tr("%1 B per cell, %2 B per occupied voxel")
                                  .arg(stats.voxelBytesPerCell(), 0, 'f', 1)
                                  .arg(stats.voxelBytesPerOccupiedVoxel(), 0, 'f', 0));
    m_memoryPerVoxel->setToolTip(tr("%1 of the grid's cells hold a surface").arg(stats.occupiedVoxels));
    if (stats.voxelResolution > 0 && stats.gridBricks > 0)
        m_grid->setText(tr("%1, voxel %2 cm, sparse: %3 of %4 bricks stored")
                            .arg(QString::number(stats.voxelResolution) + QStringLiteral("³"))
                            .arg(double(stats.voxelSize) * 100.0, 0, 'f', 2)
                            .arg(stats.storedBricks)
                            .arg(stats.gridBricks));
    else if (stats.voxelResolution > 0)
        m_grid->setText(tr("%1, voxel %2 cm")
                            .arg(QString::number(stats.voxelResolution) + QStringLiteral("³"))
                            .arg(double(stats.voxelSize) * 100.0, 0, 'f', 2));
    else
        m_grid->setText(QStringLiteral("—"));
    m_frame->setText(
        stats.width > 0 ? tr("%1 × %2 px").arg(stats.width).arg(stats.height) : QStringLiteral("—"));
    if (stats.bounceIterations > 0)
        m_bounces->setText(
            tr("%1, %2 %3%4")
                .arg(stats.bounceIterations)
                .arg(stats.bounceExtrapolated ? tr("extrapolated, est. error") : tr("residual"))
                .arg(stats.bounceResidual, 0, 'g', 2)
                .arg(stats.lightConverged
                        ? (stats.bounceStoppedAtLimit ? tr(", stopped at the iteration limit") : QString())
                        : tr(", converging…")));
    else
        m_bounces->setText(tr("one bounce"));
    // Where the gathers count what walls let through as the walls' light (enclosed_space).
    if (stats.enclosedCells > 0)
        m_bounces->setText(m_bounces->text()
            + tr(" · enclosed: %1% of the grid")
                  .arg(100.0 * double(stats.enclosedCells)
                          / double(std::max<std::size_t>(stats.enclosureCells, 1)),
                      0, 'f', 1));
}

} // namespace vct::ui
