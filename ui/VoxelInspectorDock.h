#pragma once

#include "InspectorSettings.h"

#include <QDockWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QSlider;

namespace vct::ui {

/**
 * Chooses what the voxel inspector draws beside the cone-traced image: on/off, mip level (0 = finest up to
 * the coarsest) and channel; shows how many cubes were drawn and the voxel under the cursor. Knows no GL:
 * the viewport draws, this panel only asks.
 */
class VoxelInspectorDock : public QDockWidget {
    Q_OBJECT

public:
    explicit VoxelInspectorDock(QWidget* parent = nullptr);
    InspectorSettings settings() const;
    void setSettings(const InspectorSettings& settings);
    QSlider* levelSlider() const { return m_level; }
    QComboBox* channelBox() const { return m_channel; }
    QCheckBox* enabledBox() const { return m_enabled; }
    QLabel* countLabel() const { return m_count; }

public slots:
    void setLevelCount(int levels);
    void setCubeCount(int count, int levels);
    void setHoverText(const QString& text);

signals:
    void settingsChanged(const vct::ui::InspectorSettings& settings);

private:
    void emitSettings();
    QCheckBox* m_enabled;
    QSlider* m_level;
    QLabel* m_levelLabel;
    QComboBox* m_channel;
    QLabel* m_count;
    QLabel* m_hover;
};

} // namespace vct::ui
