#include "TestSupport.h"

#include "document/ModelImporter.h"

#include <QtTest>

/** Model files the fuzzer (scripts/fuzz) found to crash or hang the importer, kept as regressions. */
class ModelImportRegressionsTest : public QObject {
    Q_OBJECT

private slots:
    void damagedPlyHeaderFailsInsteadOfLooping();
};

// A PLY header whose last property line runs into end_header sent Assimp 5.2 into an endless read/seek loop:
// before the fix this test never returned (ctest's timeout would fail it).
void ModelImportRegressionsTest::damagedPlyHeaderFailsInsteadOfLooping()
{
    const QString path = vct::test::sourceDir() + QStringLiteral("/tests/fuzz/corpus/model/regression-ply-header-loop.ply");
    QVERIFY(QFile::exists(path));
    vct::render::Scene scene;
    QString error;
    const bool imported = vct::doc::ModelImporter::importModel(path, scene, &error);
    QVERIFY2(!imported, "a damaged file must not import");
    QVERIFY2(error.contains(QStringLiteral("regression-ply-header-loop.ply")), qPrintable(error));
}

QTEST_GUILESS_MAIN(ModelImportRegressionsTest)
#include "tst_ModelImportRegressions.moc"
