// libFuzzer target: the model importer (Assimp behind our wrapper) must turn any bytes into a scene or an
// error, never a crash. The format is picked from the first bytes as a user's file extension would.
#include "document/ImportReport.h"
#include "import/ModelImporter.h"
#include "scene/Scene.h"

#include <QDir>
#include <QFile>

#include <cstddef>
#include <cstdint>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char*>(data), qsizetype(size));
    const char* extension = bytes.startsWith("ply") ? "ply"
        : bytes.startsWith("{")                     ? "gltf"
        : bytes.startsWith("solid")                 ? "stl"
                                                    : "obj";
    static const QString dir = QDir::tempPath() + QStringLiteral("/vct-fuzz-") + QString::number(getpid());
    QDir().mkpath(dir);
    const QString path = dir + QStringLiteral("/input.") + QLatin1String(extension);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return 0;
    file.write(bytes);
    file.close();
    vct::render::Scene scene;
    QString error;
    vct::doc::ImportReport report;
    vct::doc::ModelImporter::importModel(path, scene, &error, &report);
    return 0;
}
