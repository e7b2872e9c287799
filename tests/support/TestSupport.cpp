#include "TestSupport.h"

#include <QDir>
#include <QProcessEnvironment>

namespace vct::test {

namespace {

QString env(const char* name, const QString& fallback)
{
    const QString value = QProcessEnvironment::systemEnvironment().value(QString::fromLatin1(name));
    return value.isEmpty() ? fallback : value;
}

} // namespace

QString sourceDir()
{
    return env("VCT_SOURCE_DIR", QDir::currentPath());
}

QString referenceDir()
{
    return env("VCT_SHARED_DIR", sourceDir() + QStringLiteral("/../shared")) + QStringLiteral("/reference");
}

QString outputDir()
{
    const QString dir = env("VCT_TEST_OUTPUT_DIR", QDir::tempPath() + QStringLiteral("/vct-test-output"));
    QDir().mkpath(dir);
    return dir;
}

} // namespace vct::test
