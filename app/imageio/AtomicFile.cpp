#include "AtomicFile.h"

#include <QSaveFile>
#include <QString>

namespace vct::io {

bool AtomicFile::write(const std::filesystem::path& path, std::string_view bytes, std::string* error)
{
    auto fail = [&](const QString& why) {
        if (error)
            *error = path.string() + ": " + why.toStdString();
        return false;
    };
    QSaveFile file(QString::fromStdString(path.string()));
    if (!file.open(QIODevice::WriteOnly))
        return fail(QStringLiteral("cannot open for writing (%1)").arg(file.errorString()));
    const auto size = qint64(bytes.size());
    if (file.write(bytes.data(), size) != size) {
        const QString why = file.errorString();
        file.cancelWriting();
        return fail(QStringLiteral("write failed (%1)").arg(why));
    }
    if (!file.commit())
        return fail(QStringLiteral("cannot replace the file (%1)").arg(file.errorString()));
    return true;
}

} // namespace vct::io
