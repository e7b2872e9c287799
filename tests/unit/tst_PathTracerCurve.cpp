#include "cli/AccuracyReport.h"
#include "cli/PathTracerCurve.h"

#include <QtTest>

#include <cmath>

using namespace vct::cli;

class PathTracerCurveTest : public QObject {
    Q_OBJECT

private slots:
    void interpolatesInLogLog();
    void reportsWhenOutsideTheCurve();
    void reportMarksTheFrontierAndTheCrossing();
};

namespace {

AccuracyRow tracer(int spp, double ms, double relMse)
{
    AccuracyRow row;
    row.kind = "reference";
    row.label = std::to_string(spp) + " spp";
    row.spp = spp;
    row.wallMs = ms;
    row.relMse = relMse;
    return row;
}

AccuracyRow vctPoint(const std::string& label, double ms, double relMse)
{
    AccuracyRow row;
    row.kind = "vct";
    row.label = label;
    row.gpuMs = ms;
    row.relMse = relMse;
    return row;
}

// Error halves as samples (and time) double: the Monte Carlo 1/N law.
std::vector<AccuracyRow> idealCurve()
{
    return { tracer(4, 400, 0.25), tracer(1, 100, 1.0), tracer(2, 200, 0.5), tracer(8, 800, 0.125) };
}

} // namespace

void PathTracerCurveTest::interpolatesInLogLog()
{
    const PathTracerCurve curve(idealCurve());
    QCOMPARE(curve.points().front().spp, 1); // sorted by spp
    const PathTracerTime t = curve.timeToReach(std::sqrt(0.5 * 0.25)); // halfway between 2 and 4 spp in log
    QCOMPARE(int(t.kind), int(PathTracerTime::Kind::Interpolated));
    QVERIFY(std::abs(t.ms - std::sqrt(200.0 * 400.0)) < 1e-6);
    QVERIFY(std::abs(t.spp - std::sqrt(8.0)) < 1e-9);
    QCOMPARE(curve.timeToReach(0.5).ms, 200.0); // a measured point exactly
}

void PathTracerCurveTest::reportsWhenOutsideTheCurve()
{
    const PathTracerCurve curve(idealCurve());
    const PathTracerTime easy = curve.timeToReach(2.0);
    QCOMPARE(int(easy.kind), int(PathTracerTime::Kind::AtMost));
    QCOMPARE(easy.ms, 100.0);
    const PathTracerTime hard = curve.timeToReach(0.01);
    QCOMPARE(int(hard.kind), int(PathTracerTime::Kind::Beyond));
    QCOMPARE(hard.ms, 800.0);
    QCOMPARE(int(curve.timeToReach(std::nan("")).kind), int(PathTracerTime::Kind::None));
    QCOMPARE(int(PathTracerCurve({}).timeToReach(0.1).kind), int(PathTracerTime::Kind::None));
}

void PathTracerCurveTest::reportMarksTheFrontierAndTheCrossing()
{
    std::vector<AccuracyRow> rows = idealCurve();
    rows.push_back(vctPoint("fast", 50, 0.6));
    rows.push_back(vctPoint("slow and worse", 300, 0.7));
    rows.push_back(vctPoint("good", 150, 0.3));
    for (std::size_t i = 0; i < rows.size(); ++i)
        rows[i].point = int(i);
    const AccuracyReport report("test", "header", rows);
    std::vector<std::string> frontier;
    for (std::size_t i : report.frontier())
        frontier.push_back(report.rows()[i].label);
    QCOMPARE(frontier, (std::vector<std::string> { "fast", "good" }));

    const std::string markdown = report.markdown();
    // At 100 ms VCT's best is 0.6 against 1.0; at 200 ms the path tracer's 0.5 is still worse than "good"
    // (0.3); at 400 ms its 0.25 wins.
    QVERIFY2(markdown.find("between 2 spp") != std::string::npos, markdown.c_str());
    QVERIFY(markdown.find("and 4 spp") != std::string::npos);
    QVERIFY(markdown.find("| **good** |") != std::string::npos);
    QVERIFY(markdown.find("| slow and worse |") != std::string::npos);
    const vct::plot::Chart chart = report.chart();
    QCOMPARE(chart.series.size(), std::size_t(3)); // VCT, VCT camera-only, path tracer
    QCOMPARE(chart.series[0].points.size(), std::size_t(3));
    QCOMPARE(chart.series[0].highlighted.size(), std::size_t(2));
    QCOMPARE(chart.series[2].points.size(), std::size_t(4));
}

QTEST_APPLESS_MAIN(PathTracerCurveTest)
#include "tst_PathTracerCurve.moc"
