#pragma once

#include <QDockWidget>

class QLabel;
class QTableWidget;

namespace vct::render {
struct FrameStats;
}

namespace vct::ui {

/**
 * Per-frame figures: one row per pipeline pass (name, run/reused/skipped, why, GPU time in ms) and totals.
 * It knows no renderer: the viewport hands it each frame's FrameStats through showStats().
 */
class StatsDock : public QDockWidget {
    Q_OBJECT

public:
    explicit StatsDock(QWidget* parent = nullptr);

    /** Replaces the table and labels with `stats`. Cheap enough to call every frame. */
    void showStats(const vct::render::FrameStats& stats);

    QTableWidget* table() const { return m_table; }

private:
    QTableWidget* m_table = nullptr;
    QLabel* m_total = nullptr;
    QLabel* m_memory = nullptr;
    QLabel* m_memoryPerVoxel = nullptr;
    QLabel* m_grid = nullptr;
    QLabel* m_frame = nullptr;
    QLabel* m_bounces = nullptr;
};

} // namespace vct::ui
