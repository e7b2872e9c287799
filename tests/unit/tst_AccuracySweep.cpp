#include "cli/AccuracySweep.h"

#include <QtTest>

using namespace vct;
using namespace vct::cli;

class AccuracySweepTest : public QObject {
    Q_OBJECT

private slots:
    void baseThenAxesThenPresets();
    void duplicatesAreMeasuredOnce();
    void numbersAndBooleansAreAccepted();
    void badSpecsNameTheProblem();
    void committedSpecsParse();
};

namespace {

AccuracySweep parsed(const char* json)
{
    AccuracySweep sweep;
    std::string error;
    if (!AccuracySweep::parse(json, render::RenderSettings(), sweep, &error))
        qWarning("%s", error.c_str());
    return sweep;
}

std::vector<std::string> labels(const AccuracySweep& sweep)
{
    std::vector<std::string> out;
    for (const SweepPoint& p : sweep.points())
        out.push_back(p.label);
    return out;
}

} // namespace

void AccuracySweepTest::baseThenAxesThenPresets()
{
    const AccuracySweep sweep = parsed(R"({"base": {"voxel_res": "64"},
        "axes": [{"key": "voxel_res", "values": ["32", "128"]}, {"key": "step", "values": ["0.5"]}],
        "presets": [{"label": "fine", "set": {"voxel_res": "256", "diffuse_cones": "9"}}]})");
    QCOMPARE(labels(sweep),
        (std::vector<std::string> { "base", "voxel_res=32", "voxel_res=128", "step=0.5", "fine" }));
    // One at a time: each axis point keeps the base's other settings.
    QCOMPARE(sweep.points()[0].settings.voxelResolution, 64);
    QCOMPARE(sweep.points()[1].settings.voxelResolution, 32);
    QCOMPARE(sweep.points()[3].settings.voxelResolution, 64);
    QCOMPARE(sweep.points()[3].settings.stepFactor, 0.5f);
    QCOMPARE(sweep.points()[4].settings.voxelResolution, 256);
    QCOMPARE(sweep.points()[4].settings.diffuseConeCount, 9);
    QCOMPARE(sweep.points()[4].setting, std::string("preset"));
    // JSON objects have no order: assignments are applied, and listed, by key.
    QCOMPARE(sweep.points()[4].value, std::string("diffuse_cones=9 voxel_res=256"));
    QCOMPARE(sweep.points()[1].setting, std::string("voxel_res"));
    QCOMPARE(sweep.points()[1].value, std::string("32"));
}

void AccuracySweepTest::duplicatesAreMeasuredOnce()
{
    // 128 is the default grid, so voxel_res=128 is the base; the "default" preset is too, and says so.
    const AccuracySweep sweep = parsed(R"({"axes": [{"key": "voxel_res", "values": ["64", "128"]}],
        "presets": [{"label": "default", "set": {}}, {"label": "coarse", "set": {"voxel_res": "64"}}]})");
    QCOMPARE(labels(sweep), (std::vector<std::string> { "base = default", "voxel_res=64 = coarse" }));
}

void AccuracySweepTest::numbersAndBooleansAreAccepted()
{
    const AccuracySweep sweep = parsed(R"({"axes": [{"key": "step", "values": [0.75]},
        {"key": "indirect_specular", "values": [false]}]})");
    QCOMPARE(labels(sweep), (std::vector<std::string> { "base", "step=0.75", "indirect_specular=off" }));
    QCOMPARE(sweep.points()[1].settings.stepFactor, 0.75f);
    QVERIFY(!sweep.points()[2].settings.indirectSpecular);
}

void AccuracySweepTest::badSpecsNameTheProblem()
{
    const std::pair<const char*, const char*> cases[] = {
        { "[1, 2]", "JSON object" },
        { "{\"axes\": [{\"key\": \"voxel_res\", \"values\": [\"100\"]}]}", "voxel_res" },
        { "{\"axes\": [{\"key\": \"no_such_key\", \"values\": [\"1\"]}]}", "no_such_key" },
        { "{\"presets\": [{\"set\": {}}]}", "label" },
        { "{\"presets\": [{\"label\": \"x\", \"set\": {\"step\": \"-1\"}}]}", "preset x" },
        { "{\"axis\": []}", "unknown field 'axis'" },
    };
    for (const auto& [json, expected] : cases) {
        AccuracySweep sweep;
        std::string error;
        QVERIFY2(!AccuracySweep::parse(json, render::RenderSettings(), sweep, &error), json);
        QVERIFY2(error.find(expected) != std::string::npos, (std::string(json) + " -> " + error).c_str());
    }
}

void AccuracySweepTest::committedSpecsParse()
{
    const QDir dir(qEnvironmentVariable("VCT_SOURCE_DIR") + QStringLiteral("/docs/accuracy"));
    const QStringList specs = dir.entryList({ QStringLiteral("sweep*.json") }, QDir::Files);
    if (specs.isEmpty())
        QSKIP("no docs/accuracy/sweep*.json (VCT_SOURCE_DIR unset?)");
    for (const QString& name : specs) {
        QFile file(dir.filePath(name));
        QVERIFY(file.open(QIODevice::ReadOnly));
        AccuracySweep sweep;
        std::string error;
        QVERIFY2(AccuracySweep::parse(file.readAll().toStdString(), render::RenderSettings(), sweep, &error),
            qPrintable(name + QStringLiteral(": ") + QString::fromStdString(error)));
        QVERIFY(sweep.points().size() > 1);
    }
}

QTEST_APPLESS_MAIN(AccuracySweepTest)
#include "tst_AccuracySweep.moc"
