#include "EditorTestSetup.h"
#include "TestSupport.h"

#include "ui/AccuracyChartDock.h"
#include "ui/ImagePane.h"
#include "ui/MainWindow.h"
#include "ui/ViewportWidget.h"
#include "ui/reference/ReferenceCompareDock.h"

#include "document/Document.h"
#include "imageio/ImageMetrics.h"

#include <QAction>
#include <QElapsedTimer>
#include <QFile>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QUndoStack>
#include <QtCharts/QScatterSeries>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <memory>

using namespace vct;

/**
 * "Compare with reference" and the accuracy chart, driven through the real editor under Xvfb: the cone tracer
 * on llvmpipe and the CPU path tracer at tiny sizes, so the whole file stays well under a minute.
 */
class ReferenceCompareTest : public QObject {
    Q_OBJECT

public:
    static void initMain() { test::prepareEditorApplication(); }

private slots:
    void initTestCase();
    void cleanupTestCase();
    void comparisonSizeFollowsTheAspect();
    void compareRunsToTheTarget();
    void cancelStopsPromptlyAndKeepsThePartialResult();
    void restartWhileRunningShowsOnlyTheNewJob();
    void editsMarkTheResultStale();
    void accuracyChartPlotsBothSeries();
    void accuracyChartRejectsAFileWithoutTheColumns();

private:
    ui::ReferenceCompareDock* dock() const { return m_window->referenceCompareDock(); }
    /** Sets the size and target and starts through the menu action, as Ctrl+R does. */
    void start(int longSide, int targetSpp);
    QSize expectedSize() const;
    std::unique_ptr<ui::MainWindow> m_window;
};

void ReferenceCompareTest::initTestCase()
{
    m_window = test::showEditor(QStringLiteral("builtin:cornell"), QSize(960, 640));
    QVERIFY(m_window);
    QSignalSpy frames(m_window->viewport(), &ui::ViewportWidget::frameRendered);
    m_window->viewport()->update();
    QVERIFY2(frames.wait(20000), "the viewport rendered no frame");
    QVERIFY2(m_window->viewport()->lastError().isEmpty(), qPrintable(m_window->viewport()->lastError()));
    QVERIFY(dock());
    QVERIFY(m_window->accuracyChartDock());
    QVERIFY(!dock()->isVisible()); // hidden until asked for
}

void ReferenceCompareTest::cleanupTestCase()
{
    m_window.reset();
}

void ReferenceCompareTest::start(int longSide, int targetSpp)
{
    dock()->longSideBox()->setValue(longSide);
    dock()->targetSppBox()->setValue(targetSpp);
    auto* action = m_window->findChild<QAction*>(QStringLiteral("compareReferenceAction"));
    QVERIFY(action);
    QCOMPARE(action->shortcut(), QKeySequence(QStringLiteral("Ctrl+R")));
    action->trigger();
}

QSize ReferenceCompareTest::expectedSize() const
{
    const ui::ViewportWidget* viewport = m_window->viewport();
    return ui::ReferenceCompareDock::comparisonSize(
        dock()->longSideBox()->value(), double(viewport->width()) / double(viewport->height()));
}

void ReferenceCompareTest::comparisonSizeFollowsTheAspect()
{
    QCOMPARE(ui::ReferenceCompareDock::comparisonSize(256, 16.0 / 9.0), QSize(256, 144));
    QCOMPARE(ui::ReferenceCompareDock::comparisonSize(256, 9.0 / 16.0), QSize(144, 256));
    QCOMPARE(ui::ReferenceCompareDock::comparisonSize(48, 1.0), QSize(48, 48));
    QCOMPARE(ui::ReferenceCompareDock::comparisonSize(48, 0.0), QSize(48, 48)); // nonsense aspect: square
    QCOMPARE(ui::ReferenceCompareDock::comparisonSize(4, 100.0), QSize(4, 1));
}

void ReferenceCompareTest::compareRunsToTheTarget()
{
    QSignalSpy finished(dock(), &ui::ReferenceCompareDock::comparisonFinished);
    start(48, 16);
    QVERIFY(dock()->isVisible());
    QVERIFY(dock()->isRunning());
    QVERIFY(dock()->cancelButton()->isEnabled());
    QTRY_VERIFY_WITH_TIMEOUT(!dock()->isRunning(), 30000);
    QCOMPARE(finished.size(), 1);
    QCOMPARE(finished.front().front().toBool(), true);

    const QSize size = expectedSize();
    QCOMPARE(std::max(size.width(), size.height()), 48);
    for (const render::RadianceImage* image :
        { &dock()->vctImage(), &dock()->referenceImage(), &dock()->heatmapImage() }) {
        QCOMPARE(image->width, size.width());
        QCOMPARE(image->height, size.height());
        QCOMPARE(int(image->pixels.size()), size.width() * size.height());
    }
    for (const ui::ImagePane* pane : { dock()->vctPane(), dock()->referencePane(), dock()->heatmapPane() }) {
        QVERIFY(!pane->image().isNull());
        QCOMPARE(pane->image().size(), size);
    }
    QVERIFY(io::ImageMetrics::meanLuminance(dock()->referenceImage()) > 0.01);

    const ui::ReferenceUpdate& update = dock()->lastUpdate();
    QCOMPARE(update.samplesPerPixel, 16);
    QVERIFY(std::isfinite(update.relativeMse));
    QVERIFY(update.relativeMse > 0.0);
    const double expected = io::ImageMetrics::relativeMse(dock()->vctImage(), dock()->referenceImage());
    QCOMPARE(update.relativeMse, expected);
    QCOMPARE(dock()->relativeMseLabel()->text(), QString::number(expected, 'g', 4));
    QCOMPARE(update.rmse, io::ImageMetrics::rmse(dock()->vctImage(), dock()->referenceImage()));
    QVERIFY(update.ssim > -1.0 && update.ssim <= 1.0);

    QCOMPARE(dock()->progressBar()->maximum(), 16);
    QCOMPARE(dock()->progressBar()->value(), dock()->progressBar()->maximum());
    QVERIFY(!dock()->cancelButton()->isEnabled());
    QVERIFY2(dock()->statusLabel()->text().startsWith(QStringLiteral("Done")),
        qPrintable(dock()->statusLabel()->text()));
    QVERIFY(!dock()->isStale());

    // The comparison is a point of its own on the accuracy chart.
    const std::vector<ui::SweepResults::Point>& compared = m_window->accuracyChartDock()->comparisons();
    QCOMPARE(compared.size(), std::size_t(1));
    QCOMPARE(compared.front().relativeMse, update.relativeMse);
    QCOMPARE(compared.front().timeMs, dock()->vctGpuMs());
    QCOMPARE(m_window->accuracyChartDock()->comparisonSeries()->count(), 1);

    const QString screenshot = test::outputDir() + QStringLiteral("/reference-compare.png");
    QVERIFY(m_window->grab().save(screenshot));
    qInfo("screenshot of the comparison: %s", qPrintable(screenshot));
}

void ReferenceCompareTest::cancelStopsPromptlyAndKeepsThePartialResult()
{
    const int target = dock()->targetSppBox()->maximum();
    start(48, target);
    QVERIFY(dock()->isRunning());
    // Let a pass or two finish, so there is a partial result to keep.
    QTRY_VERIFY_WITH_TIMEOUT(dock()->lastUpdate().samplesPerPixel >= 8, 20000);
    QVERIFY(dock()->isRunning());

    QElapsedTimer clock;
    clock.start();
    QTest::mouseClick(dock()->cancelButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!dock()->isRunning(), 5000);
    qInfo("the job stopped %lld ms after Cancel", static_cast<long long>(clock.elapsed()));
    QVERIFY(clock.elapsed() < 5000);

    const int spp = dock()->lastUpdate().samplesPerPixel;
    QVERIFY(spp >= 8);
    QVERIFY(spp < target);
    // The bar shows what the numbers are of, not the pass that was dropped.
    QCOMPARE(dock()->progressBar()->value(), spp);
    QCOMPARE(dock()->referenceImage().width, expectedSize().width());
    QVERIFY(!dock()->referencePane()->image().isNull());
    QVERIFY2(dock()->statusLabel()->text().startsWith(QStringLiteral("Cancelled")),
        qPrintable(dock()->statusLabel()->text()));
}

void ReferenceCompareTest::restartWhileRunningShowsOnlyTheNewJob()
{
    QSignalSpy finished(dock(), &ui::ReferenceCompareDock::comparisonFinished);
    start(40, dock()->targetSppBox()->maximum());
    QTRY_VERIFY_WITH_TIMEOUT(dock()->lastUpdate().samplesPerPixel >= 4, 20000);
    QVERIFY(dock()->isRunning());

    // Asking again while the first job runs cancels it; its late signals must not reach the display.
    start(32, 8);
    QTRY_VERIFY_WITH_TIMEOUT(!dock()->isRunning(), 30000);
    QCOMPARE(finished.size(), 1);
    QCOMPARE(finished.front().front().toBool(), true);
    QCOMPARE(dock()->lastUpdate().samplesPerPixel, 8);
    const QSize size = expectedSize();
    QCOMPARE(std::max(size.width(), size.height()), 32);
    QCOMPARE(dock()->referenceImage().width, size.width());
    QCOMPARE(dock()->vctImage().width, size.width());
    QCOMPARE(dock()->progressBar()->maximum(), 8);
    QCOMPARE(dock()->progressBar()->value(), 8);
    // Nothing more arrives from the cancelled job.
    QTest::qWait(300);
    QCOMPARE(finished.size(), 1);
    QCOMPARE(dock()->referenceImage().width, size.width());
}

void ReferenceCompareTest::editsMarkTheResultStale()
{
    QVERIFY(!dock()->isStale());
    QVERIFY(!dock()->staleLabel()->isVisibleTo(dock()));
    render::Camera camera = m_window->document()->state().camera;
    camera.position.x += 0.25f;
    m_window->document()->setCamera(camera);
    QVERIFY(dock()->isStale());
    QVERIFY(dock()->staleLabel()->isVisibleTo(dock()));

    start(16, 4);
    QVERIFY(!dock()->isStale());
    QTRY_VERIFY_WITH_TIMEOUT(!dock()->isRunning(), 30000);
    QCOMPARE(dock()->lastUpdate().samplesPerPixel, 4);
}

void ReferenceCompareTest::accuracyChartPlotsBothSeries()
{
    ui::AccuracyChartDock* chart = m_window->accuracyChartDock();
    const QString path = test::outputDir() + QStringLiteral("/sweep-results.csv");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    // As vct-bench accuracy writes it (path-tracer rows: wall_ms, no gpu_ms), plus an unknown column, a
    // quoted label with a comma and one row a log chart cannot show.
    file.write("kind,label,voxel_res,gpu_ms,rel_mse,ssim,wall_ms,extra\n"
               "vct,vct 64,64,3.5,0.04,0.91,5,x\n"
               "vct,\"vct 128, anisotropic\",128,12.25,0.02,0.95,20,x\n"
               "vct,vct 256,256,40,0.012,0.97,55,x\n"
               "vct,vct broken,32,1.0,0,0.5,2,x\n"
               "reference,reference 16 spp,,,0.08,0.6,800,x\n"
               "reference,reference 256 spp,,,0.004,0.98,12800,x\n");
    file.close();

    QString error;
    QVERIFY2(chart->loadCsv(path, &error), qPrintable(error));
    QCOMPARE(chart->vctSeries()->count(), 3);
    QCOMPARE(chart->referenceSeries()->count(), 2);
    QCOMPARE(chart->results().skippedRows(), 1);
    QCOMPARE(chart->vctSeries()->at(1), QPointF(12.25, 0.02));
    QCOMPARE(chart->referenceSeries()->at(1), QPointF(12800.0, 0.004));
    QCOMPARE(chart->results().points()[1].label, QStringLiteral("vct 128, anisotropic"));
    QCOMPARE(chart->loadedPath(), path);

    auto* action = m_window->findChild<QAction*>(QStringLiteral("accuracyChartAction"));
    QVERIFY(action);
    action->trigger();
    QVERIFY(chart->isVisible());
    QCOMPARE(chart->loadedPath(), path); // showing it does not replace a loaded sweep with the default
    const QString screenshot = test::outputDir() + QStringLiteral("/accuracy-chart.png");
    QVERIFY(chart->grab().save(screenshot));
    qInfo("screenshot of the chart: %s", qPrintable(screenshot));
}

void ReferenceCompareTest::accuracyChartRejectsAFileWithoutTheColumns()
{
    ui::AccuracyChartDock* chart = m_window->accuracyChartDock();
    const QString path = test::outputDir() + QStringLiteral("/sweep-no-error.csv");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write("label,gpu_ms\nvct,3\n");
    file.close();
    const QString before = chart->loadedPath();
    QString error;
    QVERIFY(!chart->loadCsv(path, &error));
    QVERIFY2(error.contains(QStringLiteral("rel_mse")), qPrintable(error));
    QCOMPARE(chart->loadedPath(), before);
    QCOMPARE(chart->vctSeries()->count(), 3);
}

QTEST_MAIN(ReferenceCompareTest)
#include "tst_ReferenceCompare.moc"
