#include "plot/AxisTicks.h"
#include "plot/Chart.h"
#include "plot/ChartWriter.h"
#include "plot/ParetoFrontier.h"

#include <QXmlStreamReader>
#include <QtTest>

#include <set>

using namespace vct::plot;

class ChartTest : public QObject {
    Q_OBJECT

public:
    // PNG text needs a QGuiApplication; the offscreen platform gives one without a display.
    static void initMain()
    {
        if (!qEnvironmentVariableIsSet("QT_QPA_PLATFORM"))
            qputenv("QT_QPA_PLATFORM", "offscreen");
    }

private slots:
    void svgIsWellFormedWithOneMarkerPerPoint();
    void svgEscapesText();
    void logTicksCoverKnownRanges();
    void linearTicksAreNiceSteps();
    void fixedTicksAreKept();
    void tickLabelsAreShort();
    void pngHasTheSizeAndIsNotBlank();
    void paretoFrontierOfKnownPoints();
    void paretoFrontierTiesAndDuplicates();
};

namespace {

Chart sampleChart()
{
    Chart chart;
    chart.title = QStringLiteral("cost against pixels");
    chart.x = { QStringLiteral("pixels"), AxisScale::Log10, {} };
    chart.y = { QStringLiteral("ms"), AxisScale::Log10, {} };
    ChartSeries& total = chart.addSeries(QStringLiteral("total"));
    total.points = { { 57600, 120, QStringLiteral("120 ms") }, { 230400, 410, QStringLiteral("410 ms") },
        { 921600, 1500, QStringLiteral("1.5 s") } };
    ChartSeries& cone = chart.addSeries(QStringLiteral("cone trace"));
    cone.points = { { 57600, 40, {} }, { 230400, 150, {} }, { 921600, 600, {} } };
    cone.dashed = true;
    cone.highlighted = { 0, 2 };
    cone.highlightName = QStringLiteral("frontier");
    return chart;
}

struct SvgSummary {
    QMap<QString, int> classes; ///< element count per class attribute
    QStringList texts; ///< every <text> content
    QString error;
};

SvgSummary readSvg(const QString& svg)
{
    SvgSummary summary;
    QXmlStreamReader xml(svg);
    bool sawRoot = false;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        if (!sawRoot) {
            sawRoot = true;
            if (xml.name() != QLatin1String("svg"))
                summary.error = QStringLiteral("root is <%1>").arg(xml.name());
        }
        const QString cls = xml.attributes().value(QLatin1String("class")).toString();
        if (!cls.isEmpty())
            ++summary.classes[cls];
        if (xml.name() == QLatin1String("text"))
            summary.texts << xml.readElementText();
    }
    if (xml.hasError())
        summary.error = xml.errorString() + QStringLiteral(" at line %1").arg(xml.lineNumber());
    return summary;
}

} // namespace

void ChartTest::svgIsWellFormedWithOneMarkerPerPoint()
{
    const SvgSummary svg = readSvg(ChartWriter::toSvg(sampleChart(), QSize(800, 500)));
    QVERIFY2(svg.error.isEmpty(), qPrintable(svg.error));
    QCOMPARE(svg.classes.value(QStringLiteral("marker")), 6);
    QCOMPARE(svg.classes.value(QStringLiteral("highlight")), 2);
    QCOMPARE(svg.classes.value(QStringLiteral("frontier")), 1);
    QCOMPARE(svg.classes.value(QStringLiteral("point-label")), 3);
    QCOMPARE(svg.classes.value(QStringLiteral("legend-label")), 3); // two series and the frontier
    for (const char* expected :
        { "cost against pixels", "pixels", "ms", "total", "cone trace", "frontier", "120 ms", "1.5 s" })
        QVERIFY2(svg.texts.contains(QLatin1String(expected)), expected);
    // Pixels 57 600 .. 921 600 span under two decades: 1-2-5 ticks; ms 40 .. 1500 span more: decades.
    for (const char* tick : { "50k", "100k", "200k", "500k", "1M", "10", "100", "1k", "10k" })
        QVERIFY2(svg.texts.contains(QLatin1String(tick)), tick);
}

void ChartTest::svgEscapesText()
{
    Chart chart;
    chart.title = QStringLiteral("a < b & \"c\" %1");
    chart.addSeries(QStringLiteral("<series>")).points = { { 1, 2, QStringLiteral("x&y") } };
    const SvgSummary svg = readSvg(ChartWriter::toSvg(chart, QSize(300, 200)));
    QVERIFY2(svg.error.isEmpty(), qPrintable(svg.error));
    QVERIFY(svg.texts.contains(QStringLiteral("a < b & \"c\" %1")));
    QVERIFY(svg.texts.contains(QStringLiteral("<series>")));
    QVERIFY(svg.texts.contains(QStringLiteral("x&y")));
}

void ChartTest::logTicksCoverKnownRanges()
{
    // Four decades: ticks on decades only, range widened to the decades around the data.
    const AxisRange wide = AxisTicks::log10(3.0, 4000.0);
    QCOMPARE(wide.min, 1.0);
    QCOMPARE(wide.max, 10000.0);
    QCOMPARE(wide.ticks, (std::vector<double> { 1.0, 10.0, 100.0, 1000.0, 10000.0 }));
    // Grid sizes 32..256 span under two decades: 1-2-5 ticks.
    const AxisRange grids = AxisTicks::log10(32.0, 256.0);
    QCOMPARE(grids.min, 20.0);
    QCOMPARE(grids.max, 500.0);
    QCOMPARE(grids.ticks, (std::vector<double> { 20.0, 50.0, 100.0, 200.0, 500.0 }));
    // Data on a tick keeps that tick as the bound; two decades still get 1-2-5 ticks.
    const AxisRange exact = AxisTicks::log10(0.1, 10.0);
    QCOMPARE(exact.min, 0.1);
    QCOMPARE(exact.max, 10.0);
    QCOMPARE(exact.ticks.size(), std::size_t(7)); // 0.1 0.2 0.5 1 2 5 10
    QVERIFY(std::abs(exact.ticks[1] - 0.2) < 1e-12);
    QCOMPARE(AxisTicks::log10(0.1, 100.0).ticks.size(), std::size_t(4)); // three decades: 0.1 1 10 100
    // Nothing usable on a log axis: a sane default.
    const AxisRange none = AxisTicks::log10(-1.0, 0.0);
    QCOMPARE(none.min, 1.0);
    QCOMPARE(none.max, 10.0);
}

void ChartTest::linearTicksAreNiceSteps()
{
    const AxisRange r = AxisTicks::linear(0.3, 9.2);
    QCOMPARE(r.min, 0.0);
    QCOMPARE(r.max, 10.0);
    QCOMPARE(r.ticks, (std::vector<double> { 0.0, 2.0, 4.0, 6.0, 8.0, 10.0 }));
    const AxisRange negative = AxisTicks::linear(-0.27, 0.41);
    QCOMPARE(negative.ticks.size(), std::size_t(6)); // steps of 0.2 from -0.4 to 0.6
    QCOMPARE(negative.ticks.front(), -0.4);
    QCOMPARE(negative.ticks.back(), 0.6);
    QVERIFY(std::find(negative.ticks.begin(), negative.ticks.end(), 0.0) != negative.ticks.end());
    const AxisRange flat = AxisTicks::linear(5.0, 5.0);
    QVERIFY(flat.min < 5.0 && flat.max > 5.0);
}

void ChartTest::fixedTicksAreKept()
{
    ChartAxis axis { QStringLiteral("grid"), AxisScale::Log10, { 256, 32, 64, 128 } };
    const AxisRange r = AxisTicks::forAxis(axis, 32.0, 256.0);
    QCOMPARE(r.ticks, (std::vector<double> { 32.0, 64.0, 128.0, 256.0 }));
    QVERIFY(r.min < 32.0 && r.max > 256.0); // padded so edge markers stay inside
}

void ChartTest::tickLabelsAreShort()
{
    QCOMPARE(AxisTicks::label(0.25), QStringLiteral("0.25"));
    QCOMPARE(AxisTicks::label(40.0), QStringLiteral("40"));
    QCOMPARE(AxisTicks::label(1500.0), QStringLiteral("1.5k"));
    QCOMPARE(AxisTicks::label(2e6), QStringLiteral("2M"));
    QCOMPARE(AxisTicks::label(0.1 + 0.2), QStringLiteral("0.3"));
}

void ChartTest::pngHasTheSizeAndIsNotBlank()
{
    QVERIFY(ChartWriter::canDrawText());
    const QImage image = ChartWriter::toImage(sampleChart(), QSize(640, 400));
    QCOMPARE(image.size(), QSize(640, 400));
    std::set<QRgb> colors;
    int dark = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QRgb c = image.pixel(x, y);
            colors.insert(c);
            dark += qGray(c) < 100;
        }
    QVERIFY2(colors.size() > 20, qPrintable(QString::number(colors.size())));
    QVERIFY2(dark > 500, qPrintable(QString::number(dark))); // text and frame drawn, not only fills

    const QString dir
        = QDir::temp().filePath(QStringLiteral("tst_Chart-%1").arg(QCoreApplication::applicationPid()));
    QVERIFY(QDir().mkpath(dir));
    QString error;
    QVERIFY2(ChartWriter::write(sampleChart(), dir + QStringLiteral("/chart"), QSize(320, 200), &error),
        qPrintable(error));
    const QImage loaded(dir + QStringLiteral("/chart.png"));
    QCOMPARE(loaded.size(), QSize(320, 200));
    QVERIFY(QFileInfo(dir + QStringLiteral("/chart.svg")).size() > 500);
    QDir(dir).removeRecursively();
}

void ChartTest::paretoFrontierOfKnownPoints()
{
    //  error
    //   5 | a           a(1,5) b(2,3) c(3,4) d(4,1) e(5,1) f(0.5,9)
    //   3 |   b   c     frontier by time: f, a, b, d  (c is beaten by b, e by d)
    //   1 |       d e
    const std::vector<TimeError> points = { { 1, 5 }, { 2, 3 }, { 3, 4 }, { 4, 1 }, { 5, 1 }, { 0.5, 9 } };
    QCOMPARE(ParetoFrontier::of(points), (std::vector<std::size_t> { 5, 0, 1, 3 }));
    QVERIFY(ParetoFrontier::of({}).empty());
    QCOMPARE(ParetoFrontier::of({ { 2, 2 } }), (std::vector<std::size_t> { 0 }));
}

void ChartTest::paretoFrontierTiesAndDuplicates()
{
    // Same time: only the more accurate; identical points: the first; NaN ignored.
    const std::vector<TimeError> points
        = { { 1, 4 }, { 1, 2 }, { 3, 1 }, { 3, 1 }, { std::nan(""), 0 }, { 2, 2 } };
    QCOMPARE(ParetoFrontier::of(points), (std::vector<std::size_t> { 1, 2 }));
}

QTEST_MAIN(ChartTest)
#include "tst_Chart.moc"
