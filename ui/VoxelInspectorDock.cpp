#include "VoxelInspectorDock.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

namespace vct::ui {

VoxelInspectorDock::VoxelInspectorDock(QWidget* parent)
    : QDockWidget(tr("Voxel inspector"), parent)
{
    setObjectName(QStringLiteral("VoxelInspectorDock"));
    auto* body = new QWidget(this);
    auto* form = new QFormLayout(body);
    m_enabled = new QCheckBox(tr("Show voxels beside the image"), body);
    m_enabled->setToolTip(
        tr("Splits the viewport: cone-traced image on the left, voxels as cubes on the right, same camera."));
    form->addRow(m_enabled);
    m_grid = new QComboBox(body);
    m_grid->setObjectName(QStringLiteral("inspectorGridCombo"));
    m_grid->setToolTip(
        tr("With a clipmap (Render settings, Grids): which of its levels to show. Level 0 is the "
           "finest, around the camera; each level out is twice as wide with cells twice as "
           "large; the last is the grid around the whole scene."));
    setGridCount(1);
    form->addRow(tr("Grid"), m_grid);
    m_level = new QSlider(Qt::Horizontal, body);
    // Room for a 512^3 grid's ten levels until the renderer reports how many there are.
    m_level->setRange(0, 9);
    m_level->setPageStep(1);
    m_level->setTickPosition(QSlider::TicksBelow);
    m_level->setToolTip(tr("Mip level: 0 is the finest grid; each level halves the resolution."));
    m_levelLabel = new QLabel(tr("level 0"), body);
    auto* levelRow = new QHBoxLayout;
    levelRow->addWidget(m_level, 1);
    levelRow->addWidget(m_levelLabel);
    form->addRow(tr("Mip level"), levelRow);
    m_channel = new QComboBox(body);
    m_channel->addItem(tr("Albedo"), int(render::VoxelChannel::Albedo));
    m_channel->addItem(tr("Radiance"), int(render::VoxelChannel::Radiance));
    m_channel->addItem(tr("Opacity"), int(render::VoxelChannel::Opacity));
    m_channel->addItem(tr("Normal"), int(render::VoxelChannel::Normal));
    m_channel->addItem(tr("Emission"), int(render::VoxelChannel::Emission));
    m_channel->setCurrentIndex(1);
    form->addRow(tr("Channel"), m_channel);
    m_count = new QLabel(tr("Cubes drawn: -"), body);
    form->addRow(m_count);
    m_hover = new QLabel(body);
    m_hover->setWordWrap(true);
    m_hover->setTextInteractionFlags(Qt::TextSelectableByMouse);
    form->addRow(m_hover);
    setWidget(body);

    connect(m_enabled, &QCheckBox::toggled, this, &VoxelInspectorDock::emitSettings);
    connect(m_grid, &QComboBox::currentIndexChanged, this, [this](int grid) {
        m_wantedGrid = std::max(0, grid);
        emitSettings();
    });
    connect(m_level, &QSlider::valueChanged, this, &VoxelInspectorDock::emitSettings);
    connect(m_channel, &QComboBox::currentIndexChanged, this, &VoxelInspectorDock::emitSettings);
}

InspectorSettings VoxelInspectorDock::settings() const
{
    return { m_enabled->isChecked(), m_level->value(), render::VoxelChannel(m_channel->currentData().toInt()),
        std::max(0, m_grid->currentIndex()) };
}

void VoxelInspectorDock::setSettings(const InspectorSettings& settings)
{
    m_enabled->setChecked(settings.enabled);
    m_wantedGrid = std::max(0, settings.grid);
    if (m_wantedGrid < m_grid->count())
        m_grid->setCurrentIndex(m_wantedGrid);
    m_level->setValue(settings.level);
    m_channel->setCurrentIndex(m_channel->findData(int(settings.channel)));
}

void VoxelInspectorDock::emitSettings()
{
    m_levelLabel->setText(tr("level %1").arg(m_level->value()));
    emit settingsChanged(settings());
}

void VoxelInspectorDock::setLevelCount(int levels)
{
    m_level->setMaximum(std::max(0, levels - 1));
}

void VoxelInspectorDock::setGridCount(int grids)
{
    grids = std::max(1, grids);
    if (grids == m_grid->count())
        return;
    // The grid asked for where the new clipmap has it, else the finest; one settings change at the end.
    const int current = std::max(0, m_grid->currentIndex());
    {
        const QSignalBlocker block(m_grid);
        m_grid->clear();
        if (grids == 1)
            m_grid->addItem(tr("The scene's grid"));
        else
            for (int grid = 0; grid < grids; ++grid)
                m_grid->addItem(grid == 0   ? tr("Level 0 (finest, around the camera)")
                        : grid == grids - 1 ? tr("Level %1 (the whole scene)").arg(grid)
                                            : tr("Level %1").arg(grid));
        m_grid->setCurrentIndex(m_wantedGrid < grids ? m_wantedGrid : 0);
        m_grid->setEnabled(grids > 1);
    }
    if (current != m_grid->currentIndex())
        emitSettings();
}

void VoxelInspectorDock::setCubeCount(int count, int levels, int grids)
{
    setGridCount(grids);
    setLevelCount(levels);
    m_count->setText(tr("Cubes drawn: %1").arg(count));
}

void VoxelInspectorDock::setHoverText(const QString& text)
{
    m_hover->setText(text);
}

} // namespace vct::ui
