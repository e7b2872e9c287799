#include "AtomicFile.h"

#include <QSaveFile>

#include <cerrno>

namespace vct::files {

QString AtomicFile::write(const QString& path, const QByteArray& bytes)
{
    QSaveFile file(path);
    errno = 0;
    if (!file.open(QIODevice::WriteOnly))
        return QStringLiteral("cannot open for writing (%1)").arg(file.errorString());
    // Qt 6.4's commit() ignores a failed final flush (a full disk, a file size limit) and would rename a
    // truncated file over the old one, so the flush is checked here first.
    if (file.write(bytes) != bytes.size() || !file.flush()) {
        // A short write leaves Qt without a message of its own; errno still holds the failed write's reason.
        const int osError = errno;
        const QString reason = osError != 0 ? qt_error_string(osError) : file.errorString();
        file.cancelWriting();
        return QStringLiteral("writing failed (%1); any old file is unchanged").arg(reason);
    }
    if (!file.commit())
        return QStringLiteral("cannot replace the file (%1); any old file is unchanged")
            .arg(file.errorString());
    return {};
}

bool AtomicFile::write(const QString& path, const QByteArray& bytes, QString* error)
{
    const QString problem = write(path, bytes);
    if (problem.isEmpty())
        return true;
    if (error)
        *error = QStringLiteral("%1: %2").arg(path, problem);
    return false;
}

bool AtomicFile::write(const QString& path, std::string_view bytes, QString* error)
{
    return write(path, QByteArray::fromRawData(bytes.data(), qsizetype(bytes.size())), error);
}

bool AtomicFile::write(const std::filesystem::path& path, std::string_view bytes, std::string* error)
{
    const QString problem = write(QString::fromStdString(path.string()),
        QByteArray::fromRawData(bytes.data(), qsizetype(bytes.size())));
    if (problem.isEmpty())
        return true;
    if (error)
        *error = path.string() + ": " + problem.toStdString();
    return false;
}

} // namespace vct::files
