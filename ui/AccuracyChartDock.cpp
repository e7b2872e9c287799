#include "AccuracyChartDock.h"

#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QLogValueAxis>
#include <QtCharts/QScatterSeries>

#include <QCoreApplication>
#include <QCursor>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QToolTip>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vct::ui {

namespace {

/** A log axis range with some room around [lo, hi], snapped outwards to powers of ten where that is close. */
void fitLogAxis(QLogValueAxis* axis, double lo, double hi)
{
    if (!(lo > 0.0) || !(hi >= lo)) {
        axis->setRange(1.0, 10.0);
        return;
    }
    axis->setRange(
        std::pow(10.0, std::floor(std::log10(lo / 1.5))), std::pow(10.0, std::ceil(std::log10(hi * 1.5))));
}

} // namespace

AccuracyChartDock::AccuracyChartDock(QWidget* parent)
    : QDockWidget(tr("Accuracy chart"), parent)
{
    setObjectName(QStringLiteral("AccuracyChartDock"));
    auto* body = new QWidget(this);

    m_chart = new QChart;
    m_chart->setTitle(tr("Error against time"));
    m_chart->legend()->setAlignment(Qt::AlignBottom);
    m_vct = new QScatterSeries(m_chart);
    m_vct->setName(tr("VCT"));
    m_vct->setMarkerSize(9.0);
    m_reference = new QScatterSeries(m_chart);
    m_reference->setName(tr("Path tracer"));
    m_reference->setMarkerShape(QScatterSeries::MarkerShapeRectangle);
    m_reference->setMarkerSize(9.0);
    m_comparison = new QScatterSeries(m_chart);
    m_comparison->setName(tr("Compared in the editor"));
    m_comparison->setMarkerShape(QScatterSeries::MarkerShapeStar);
    m_comparison->setMarkerSize(14.0);
    m_chart->addSeries(m_vct);
    m_chart->addSeries(m_reference);
    m_chart->addSeries(m_comparison);
    m_timeAxis = new QLogValueAxis(m_chart);
    m_timeAxis->setTitleText(tr("time, ms (VCT: GPU per frame; path tracer: wall clock)"));
    m_timeAxis->setLabelFormat(QStringLiteral("%g"));
    m_timeAxis->setMinorTickCount(-1);
    m_errorAxis = new QLogValueAxis(m_chart);
    m_errorAxis->setTitleText(tr("relative MSE"));
    m_errorAxis->setLabelFormat(QStringLiteral("%g"));
    m_errorAxis->setMinorTickCount(-1);
    m_chart->addAxis(m_timeAxis, Qt::AlignBottom);
    m_chart->addAxis(m_errorAxis, Qt::AlignLeft);
    for (QScatterSeries* series : { m_vct, m_reference, m_comparison }) {
        series->attachAxis(m_timeAxis);
        series->attachAxis(m_errorAxis);
    }
    fitLogAxis(m_timeAxis, 0.0, 0.0);
    fitLogAxis(m_errorAxis, 0.0, 0.0);
    connect(m_vct, &QScatterSeries::hovered, this,
        [this](const QPointF& point, bool state) { showPointTip(false, point, state); });
    connect(m_reference, &QScatterSeries::hovered, this,
        [this](const QPointF& point, bool state) { showPointTip(true, point, state); });
    connect(m_comparison, &QScatterSeries::hovered, this,
        [this](const QPointF& point, bool state) { showPointTip(false, point, state); });

    m_view = new QChartView(m_chart, body);
    m_view->setObjectName(QStringLiteral("accuracyChartView"));
    m_view->setRenderHint(QPainter::Antialiasing);
    // Below this the axis labels and titles are elided to "...".
    m_view->setMinimumSize(360, 260);

    m_open = new QPushButton(tr("Open sweep..."), body);
    m_open->setObjectName(QStringLiteral("openSweepButton"));
    m_open->setToolTip(tr("A results.csv written by vct-bench accuracy"));
    m_status = new QLabel(tr("No sweep loaded."), body);
    m_status->setObjectName(QStringLiteral("sweepStatusLabel"));
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_status->setWordWrap(true);
    auto* top = new QHBoxLayout;
    top->addWidget(m_open);
    top->addWidget(m_status, 1);

    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(top);
    layout->addWidget(m_view, 1);
    setWidget(body);

    connect(m_open, &QPushButton::clicked, this, [this] {
        const QString start = m_path.isEmpty() ? findDefaultSweep() : m_path;
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Open sweep"), start, tr("Sweep results (results.csv *.csv);;All files (*)"));
        if (path.isEmpty())
            return;
        QString error;
        if (!loadCsv(path, &error))
            m_status->setText(tr("Cannot load: %1").arg(error));
    });
}

bool AccuracyChartDock::loadCsv(const QString& path, QString* error)
{
    SweepResults results;
    if (!results.load(path, error))
        return false;
    m_results = std::move(results);
    m_path = path;
    plot();
    QString text = tr("%1: %2 VCT, %3 path-tracer points")
                       .arg(QDir::toNativeSeparators(path))
                       .arg(m_results.count(false))
                       .arg(m_results.count(true));
    if (m_results.skippedRows() > 0)
        text += tr(" (%1 rows without a positive time and error left out)").arg(m_results.skippedRows());
    m_status->setText(text);
    m_status->setToolTip(text);
    return true;
}

void AccuracyChartDock::addComparison(const QString& label, double timeMs, double relativeMse)
{
    if (!(timeMs > 0.0) || !(relativeMse > 0.0) || !std::isfinite(timeMs) || !std::isfinite(relativeMse))
        return; // not on a log chart
    m_comparisons.push_back({ label, timeMs, relativeMse, false });
    plot();
}

void AccuracyChartDock::plot()
{
    QList<QPointF> vct, reference, compared;
    double timeLo = std::numeric_limits<double>::max(), timeHi = 0.0;
    double errorLo = std::numeric_limits<double>::max(), errorHi = 0.0;
    const auto fit = [&](const SweepResults::Point& point) {
        timeLo = std::min(timeLo, point.timeMs);
        timeHi = std::max(timeHi, point.timeMs);
        errorLo = std::min(errorLo, point.relativeMse);
        errorHi = std::max(errorHi, point.relativeMse);
    };
    for (const SweepResults::Point& point : m_results.points()) {
        (point.reference ? reference : vct).append(QPointF(point.timeMs, point.relativeMse));
        fit(point);
    }
    for (const SweepResults::Point& point : m_comparisons) {
        compared.append(QPointF(point.timeMs, point.relativeMse));
        fit(point);
    }
    m_vct->replace(vct);
    m_reference->replace(reference);
    m_comparison->replace(compared);
    const bool empty = m_results.points().empty() && m_comparisons.empty();
    fitLogAxis(m_timeAxis, empty ? 0.0 : timeLo, timeHi);
    fitLogAxis(m_errorAxis, empty ? 0.0 : errorLo, errorHi);
    m_chart->setTitle(m_path.isEmpty()
            ? tr("Error against time")
            : tr("Error against time: %1").arg(QFileInfo(QFileInfo(m_path).path()).fileName()));
}

void AccuracyChartDock::showPointTip(bool reference, const QPointF& point, bool hovered)
{
    if (!hovered) {
        QToolTip::hideText();
        return;
    }
    // The series hands back the point's coordinates only: find the row nearest to it in log space.
    const SweepResults::Point* nearest = nullptr;
    double best = std::numeric_limits<double>::max();
    std::vector<SweepResults::Point> candidates = m_results.points();
    candidates.insert(candidates.end(), m_comparisons.begin(), m_comparisons.end());
    for (const SweepResults::Point& candidate : candidates) {
        if (candidate.reference != reference)
            continue;
        const double dx = std::log10(candidate.timeMs) - std::log10(point.x());
        const double dy = std::log10(candidate.relativeMse) - std::log10(point.y());
        if (const double distance = dx * dx + dy * dy; distance < best) {
            best = distance;
            nearest = &candidate;
        }
    }
    if (!nearest)
        return;
    QToolTip::showText(QCursor::pos(),
        tr("%1\nrelative MSE %2\n%3 ms")
            .arg(nearest->label)
            .arg(nearest->relativeMse, 0, 'g', 4)
            .arg(nearest->timeMs, 0, 'g', 4),
        m_view);
}

void AccuracyChartDock::showEvent(QShowEvent* event)
{
    QDockWidget::showEvent(event);
    // Looked for on first show rather than at start-up: the dock starts hidden and most sessions never open
    // it.
    if (m_triedDefault || !m_path.isEmpty())
        return;
    m_triedDefault = true;
    const QString path = findDefaultSweep();
    if (path.isEmpty()) {
        m_status->setText(tr("No sweep loaded: run vct-bench accuracy, or Open sweep..."));
        return;
    }
    QString error;
    if (!loadCsv(path, &error))
        m_status->setText(tr("Cannot load: %1").arg(error));
}

QString AccuracyChartDock::findDefaultSweep()
{
    QStringList roots;
    if (qEnvironmentVariableIsSet("VCT_SOURCE_DIR"))
        roots << qEnvironmentVariable("VCT_SOURCE_DIR");
    roots << QDir::currentPath();
    // A build directory inside the source tree (build/app/editor/vct-editor) finds the tree a few levels up.
    QDir dir(QCoreApplication::applicationDirPath());
    for (int level = 0; level < 5 && dir.cdUp(); ++level)
        roots << dir.absolutePath();

    for (const QString& root : roots) {
        const QDir accuracy(root + QStringLiteral("/docs/accuracy"));
        if (!accuracy.exists())
            continue;
        QString newest;
        QDateTime newestTime;
        for (const QFileInfo& sweep : accuracy.entryInfoList(QDir::Dirs | QDir::NoDotAndDotDot)) {
            const QFileInfo csv(sweep.absoluteFilePath() + QStringLiteral("/results.csv"));
            if (csv.isFile() && (newest.isEmpty() || csv.lastModified() > newestTime)) {
                newest = csv.absoluteFilePath();
                newestTime = csv.lastModified();
            }
        }
        if (!newest.isEmpty())
            return newest;
    }
    return {};
}

} // namespace vct::ui
