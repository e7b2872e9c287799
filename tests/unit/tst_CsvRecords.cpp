#include "files/CsvRecords.h"

#include <QtTest>

using vct::files::CsvRecords;

/** The one CSV reader behind results.csv files read back (vct-bench accuracy --merge, the Accuracy chart). */
class CsvRecordsTest : public QObject {
    Q_OBJECT

private slots:
    void quotedFieldsKeepCommasQuotesAndLineBreaks();
    void lineEndsAndBlankLines();
    void columnsAreFoundByNameWithoutCase();
};

void CsvRecordsTest::quotedFieldsKeepCommasQuotesAndLineBreaks()
{
    const auto records = CsvRecords::parse("label,rel_mse\n\"a, \"\"b\"\"\nc\",0.5\n");
    QCOMPARE(records.size(), std::size_t(2));
    QCOMPARE(records[1].size(), std::size_t(2));
    QCOMPARE(records[1][0], std::string("a, \"b\"\nc"));
    QCOMPARE(records[1][1], std::string("0.5"));
    // An empty last field is a field.
    QCOMPARE(CsvRecords::parse("a,\n").front().size(), std::size_t(2));
}

void CsvRecordsTest::lineEndsAndBlankLines()
{
    const auto records = CsvRecords::parse("\r\nkind,label\r\n\r\nvct,x\r\nreference,y");
    QCOMPARE(records.size(), std::size_t(3));
    QCOMPARE(records[0][1], std::string("label"));
    QCOMPARE(records[2][0], std::string("reference"));
    QCOMPARE(records[2][1], std::string("y"));
    QVERIFY(CsvRecords::parse("").empty());
}

void CsvRecordsTest::columnsAreFoundByNameWithoutCase()
{
    const std::vector<std::string> header { "Label", " GPU_ms ", "wall_ms" };
    QCOMPARE(CsvRecords::column(header, { "gpu_ms" }), 1);
    QCOMPARE(CsvRecords::column(header, { "time_ms", "wall_ms" }), 2);
    QCOMPARE(CsvRecords::column(header, { "label" }), 0);
    QCOMPARE(CsvRecords::column(header, { "seconds" }), -1);
}

QTEST_APPLESS_MAIN(CsvRecordsTest)
#include "tst_CsvRecords.moc"
