#pragma once

#include "InspectorSettings.h"

#include <QDockWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QSlider;

namespace vct::ui {

/**
 * Chooses what the voxel inspector draws beside the cone-traced image: on/off, the grid (a clipmap's level;
 * one for a dense grid), mip level (0 = finest up to the coarsest) and channel; shows how many cubes were
 * drawn and the voxel under the cursor. Knows no GL: the viewport draws, this panel only asks.
 */
class VoxelInspectorDock : public QDockWidget {
    Q_OBJECT

public:
    explicit VoxelInspectorDock(QWidget* parent = nullptr);
    InspectorSettings settings() const;
    void setSettings(const InspectorSettings& settings);
    QSlider* levelSlider() const { return m_level; }
    QComboBox* gridBox() const { return m_grid; }
    QComboBox* channelBox() const { return m_channel; }
    QCheckBox* enabledBox() const { return m_enabled; }
    QLabel* countLabel() const { return m_count; }

public slots:
    void setLevelCount(int levels);
    /** Offers grids 0 .. @p grids - 1 (a clipmap's levels); a dense grid's one leaves the choice off. */
    void setGridCount(int grids);
    void setCubeCount(int count, int levels, int grids);
    void setHoverText(const QString& text);

signals:
    void settingsChanged(const vct::ui::InspectorSettings& settings);

private:
    void emitSettings();
    QCheckBox* m_enabled;
    QComboBox* m_grid;
    /// The grid asked for (by the user or setSettings): kept while the renderer has fewer, and taken again
    /// when a clipmap has it.
    int m_wantedGrid = 0;
    QSlider* m_level;
    QLabel* m_levelLabel;
    QComboBox* m_channel;
    QLabel* m_count;
    QLabel* m_hover;
};

} // namespace vct::ui
