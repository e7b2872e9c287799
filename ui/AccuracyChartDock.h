#pragma once

#include "SweepResults.h"

#include <QDockWidget>

class QChart;
class QChartView;
class QLabel;
class QLogValueAxis;
class QPushButton;
class QScatterSeries;

namespace vct::ui {

/**
 * The accuracy/time chart of an accuracy sweep: relative MSE (log y) against time in ms (log x) from the
 * sweep's results.csv, cone-traced configurations and path-tracer runs as two series; hovering a point shows
 * its label and values. Opens docs/accuracy/<newest>/results.csv on first show when there is one, or any file
 * through "Open sweep...".
 */
class AccuracyChartDock : public QDockWidget {
    Q_OBJECT

public:
    explicit AccuracyChartDock(QWidget* parent = nullptr);

    /** Loads and plots a results.csv; on failure keeps the current chart and returns false with @p error. */
    bool loadCsv(const QString& path, QString* error = nullptr);
    /**
     * The newest docs/accuracy/ * /results.csv under the source tree ($VCT_SOURCE_DIR, the working directory
     * or a parent of the executable's folder), or an empty string.
     */
    static QString findDefaultSweep();

    /**
     * A comparison made in the editor (Render > Compare with reference): a point of its own series beside the
     * sweep's, kept for the session. Ignored unless time and error are positive.
     */
    void addComparison(const QString& label, double timeMs, double relativeMse);
    const std::vector<SweepResults::Point>& comparisons() const { return m_comparisons; }
    QScatterSeries* comparisonSeries() const { return m_comparison; }

    QString loadedPath() const { return m_path; }
    const SweepResults& results() const { return m_results; }
    QChartView* chartView() const { return m_view; }
    QScatterSeries* vctSeries() const { return m_vct; }
    QScatterSeries* referenceSeries() const { return m_reference; }
    QPushButton* openButton() const { return m_open; }
    QLabel* statusLabel() const { return m_status; }

protected:
    void showEvent(QShowEvent* event) override;

private:
    void plot();
    void showPointTip(bool reference, const QPointF& point, bool hovered);

    SweepResults m_results;
    QString m_path;
    bool m_triedDefault = false;
    QChartView* m_view;
    QChart* m_chart;
    QScatterSeries* m_vct;
    QScatterSeries* m_reference;
    QScatterSeries* m_comparison;
    std::vector<SweepResults::Point> m_comparisons;
    QLogValueAxis* m_timeAxis;
    QLogValueAxis* m_errorAxis;
    QPushButton* m_open;
    QLabel* m_status;
};

} // namespace vct::ui
