#include "TestSupport.h"

#include "import/ModelImporter.h"

#include <QtTest>

/** Model files the fuzzer (scripts/fuzz) found to crash or hang the importer, kept as regressions. */
class ModelImportRegressionsTest : public QObject {
    Q_OBJECT

private slots:
    void damagedPlyHeaderFailsInsteadOfLooping();
    void damagedPlyHeaderFailsInsteadOfOverreading();
    void inconsistentPlyFailsInsteadOfAborting();
};

namespace {

/** The corpus file @p name must fail to import with a message naming it and containing @p phrase. */
void expectRefused(const QString& name, const QString& phrase)
{
    const QString path = vct::test::sourceDir() + QStringLiteral("/tests/fuzz/corpus/model/") + name;
    QVERIFY(QFile::exists(path));
    vct::render::Scene scene;
    QString error;
    QVERIFY2(!vct::doc::ModelImporter::importModel(path, scene, &error), "a damaged file must not import");
    QVERIFY2(error.contains(name), qPrintable(error));
    QVERIFY2(error.contains(phrase), qPrintable(error));
    QVERIFY(scene.meshes.empty());
}

} // namespace

// A PLY header whose last property line runs into end_header sent Assimp 5.2 into an endless read/seek loop:
// before the fix this test never returned (ctest's timeout would fail it).
void ModelImportRegressionsTest::damagedPlyHeaderFailsInsteadOfLooping()
{
    expectRefused(QStringLiteral("regression-ply-header-loop.ply"), QStringLiteral("cannot import model"));
}

// A PLY header with a NUL inside a half-overwritten property line made Assimp 5.2 read past its buffer
// (a SEGV under AddressSanitizer, silent corruption without it). ModelPreflight now refuses the header.
void ModelImportRegressionsTest::damagedPlyHeaderFailsInsteadOfOverreading()
{
    expectRefused(QStringLiteral("regression-ply-header-overread.ply"), QStringLiteral("PLY header"));
}

// A PLY whose header counts 2 vertices but whose face uses a third tripped an assertion inside Assimp's
// triangulation step, and Debian's Assimp aborts on assertions: the process died. Now the import fails.
void ModelImportRegressionsTest::inconsistentPlyFailsInsteadOfAborting()
{
    expectRefused(QStringLiteral("regression-ply-assert-triangulate.ply"), QStringLiteral("inconsistent"));
}

QTEST_GUILESS_MAIN(ModelImportRegressionsTest)
#include "tst_ModelImportRegressions.moc"
