// libFuzzer target: the project-file parser must reject any bytes with an error, never crash or hang.
#include "document/DocumentState.h"
#include "document/ProjectFile.h"

#include <QByteArray>
#include <QDir>

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    vct::doc::DocumentState state;
    QString error;
    vct::doc::ProjectFile::fromJson(QByteArray(reinterpret_cast<const char*>(data), qsizetype(size)),
        QDir::tempPath(), QStringLiteral("fuzz.vctproj"), &state, &error);
    return 0;
}
