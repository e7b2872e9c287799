#include "cli/AccuracyCsv.h"

#include <QtTest>

#include <cmath>

using namespace vct::cli;

class AccuracyCsvTest : public QObject {
    Q_OBJECT

private slots:
    void roundTripKeepsEveryField();
    void columnsAreFoundByName();
    void badInputIsRefused();
};

void AccuracyCsvTest::roundTripKeepsEveryField()
{
    AccuracyRow vct;
    vct.point = 3;
    vct.kind = "vct";
    vct.label = "fast, \"coarse\"";
    vct.setting = "preset";
    vct.value = "voxel_res=64 step=1.5";
    vct.gpuMs = 123.456789;
    vct.coneMs = 40.5;
    vct.cameraMs = 60.25;
    vct.relMse = 0.0123456789;
    vct.rmse = 0.1;
    vct.psnr = std::numeric_limits<double>::infinity();
    vct.ssim = 0.9;
    vct.meanRatio = 0.75;
    vct.wallMs = 130.0;
    vct.width = 256;
    vct.height = 128;
    vct.jobs = 12;
    vct.machine = "llvmpipe (LLVM 15.0.6, 256 bits)";
    AccuracyRow reference;
    reference.point = 11;
    reference.kind = "reference";
    reference.label = "16 spp";
    reference.spp = 16;
    reference.wallMs = 900.0;
    reference.relMse = 0.5;

    std::vector<AccuracyRow> rows;
    std::string error;
    QVERIFY2(
        AccuracyCsv::read(AccuracyCsv::write({ vct, reference }), "memory", rows, &error), error.c_str());
    QCOMPARE(rows.size(), std::size_t(2));
    const AccuracyRow& a = rows[0];
    QCOMPARE(a.point, 3);
    QCOMPARE(a.label, vct.label);
    QCOMPARE(a.value, vct.value);
    QCOMPARE(a.gpuMs, vct.gpuMs);
    QCOMPARE(a.relMse, vct.relMse);
    QVERIFY(std::isinf(a.psnr) && a.psnr > 0);
    QCOMPARE(a.width, 256);
    QCOMPARE(a.jobs, 12);
    QCOMPARE(a.machine, vct.machine);
    QVERIFY(std::isnan(a.wallMs) == false);
    const AccuracyRow& b = rows[1];
    QCOMPARE(b.kind, std::string("reference"));
    QCOMPARE(b.spp, 16);
    QVERIFY(std::isnan(b.gpuMs)); // not applicable: an empty field, read back as NaN
    QVERIFY(std::isnan(b.ssim));
    QVERIFY(!b.isVct());
    QCOMPARE(b.timeMs(), 900.0);
}

void AccuracyCsvTest::columnsAreFoundByName()
{
    std::vector<AccuracyRow> rows;
    std::string error;
    QVERIFY2(
        AccuracyCsv::read("point,extra,label,kind,gpu_ms\r\n0,x,base,vct,12.5\r\n", "memory", rows, &error),
        error.c_str());
    QCOMPARE(rows.size(), std::size_t(1));
    QCOMPARE(rows[0].label, std::string("base"));
    QCOMPARE(rows[0].gpuMs, 12.5);
    QVERIFY(std::isnan(rows[0].relMse));
}

void AccuracyCsvTest::badInputIsRefused()
{
    std::vector<AccuracyRow> rows;
    std::string error;
    QVERIFY(!AccuracyCsv::read("", "empty.csv", rows, &error));
    QVERIFY(error.find("empty.csv") != std::string::npos);
    QVERIFY(!AccuracyCsv::read("label,kind\nbase,vct\n", "x.csv", rows, &error));
    QVERIFY(error.find("point") != std::string::npos);
    QVERIFY(!AccuracyCsv::read("point,label,kind,gpu_ms\n0,base,vct,fast\n", "x.csv", rows, &error));
    QVERIFY(error.find("gpu_ms") != std::string::npos);
    QVERIFY(!AccuracyCsv::read("point,label,kind\n0,base,gl\n", "x.csv", rows, &error));
    QVERIFY(rows.empty()); // nothing appended from a file that failed
}

QTEST_APPLESS_MAIN(AccuracyCsvTest)
#include "tst_AccuracyCsv.moc"
