#include "QtAssimpIOSystem.h"

#include "QtAssimpIOStream.h"

#include <QFileInfo>
#include <QString>

#include <memory>

namespace vct::doc {

QtAssimpIOSystem::QtAssimpIOSystem() = default;

QtAssimpIOSystem::~QtAssimpIOSystem() = default;

bool QtAssimpIOSystem::Exists(const char* path) const
{
    return QFileInfo(QString::fromUtf8(path)).isFile();
}

char QtAssimpIOSystem::getOsSeparator() const
{
    // QFile takes '/' on every platform, and Qt resource paths only work with '/'.
    return '/';
}

Assimp::IOStream* QtAssimpIOSystem::Open(const char* path, const char* mode)
{
    auto stream = std::make_unique<QtAssimpIOStream>(QString::fromUtf8(path));
    if (!stream->open(mode ? mode : "rb"))
        return nullptr;
    return stream.release();
}

void QtAssimpIOSystem::Close(Assimp::IOStream* stream)
{
    delete stream;
}

} // namespace vct::doc
