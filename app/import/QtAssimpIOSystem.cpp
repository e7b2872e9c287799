#include "QtAssimpIOSystem.h"

#include "QtAssimpIOStream.h"

#include <QDir>
#include <QFileInfo>

#include <memory>

namespace vct::doc {

namespace {

/** The path with links resolved when it exists (Qt resources have no links: they keep their clean path). */
QString resolvedPath(const QString& path)
{
    const QFileInfo info(path);
    const QString canonical = info.canonicalFilePath();
    return canonical.isEmpty() ? QDir::cleanPath(info.absoluteFilePath()) : canonical;
}

} // namespace

QtAssimpIOSystem::QtAssimpIOSystem(const QString& modelPath, QStringList* refusals)
    : m_root(resolvedPath(QFileInfo(modelPath).absolutePath()) + QLatin1Char('/'))
    , m_refusals(refusals)
{
}

QtAssimpIOSystem::~QtAssimpIOSystem() = default;

QString QtAssimpIOSystem::refusalReason(const QString& path) const
{
    const QFileInfo info(path);
    if (!info.exists())
        return {}; // Opening fails on its own, with Assimp's usual "file not found".
    if (!resolvedPath(path).startsWith(m_root))
        return QStringLiteral("it is outside the model's folder");
    if (!info.isFile())
        return QStringLiteral("it is not a regular file");
    return {};
}

bool QtAssimpIOSystem::Exists(const char* path) const
{
    const QString name = QString::fromUtf8(path);
    return QFileInfo(name).isFile() && refusalReason(name).isEmpty();
}

char QtAssimpIOSystem::getOsSeparator() const
{
    // QFile takes '/' on every platform, and Qt resource paths only work with '/'.
    return '/';
}

Assimp::IOStream* QtAssimpIOSystem::Open(const char* path, const char* mode)
{
    const QString name = QString::fromUtf8(path);
    if (const QString reason = refusalReason(name); !reason.isEmpty()) {
        if (m_refusals)
            m_refusals->append(
                QStringLiteral("'%1' was not read: %2").arg(QDir::toNativeSeparators(name), reason));
        return nullptr;
    }
    auto stream = std::make_unique<QtAssimpIOStream>(name);
    if (!stream->open(mode ? mode : "rb"))
        return nullptr;
    return stream.release();
}

void QtAssimpIOSystem::Close(Assimp::IOStream* stream)
{
    delete stream;
}

} // namespace vct::doc
