#pragma once

#include <QByteArray>
#include <QString>

#include <filesystem>
#include <string>
#include <string_view>

namespace vct::files {

/**
 * Replaces a file's contents all at once, the one way every file we write is written (projects, camera
 * files, images, stats, reports, charts): the bytes go to a temporary file in the target's directory, which
 * is renamed over the target only when every byte is written and flushed. A failed write (a full disk, a file
 * size limit, a missing folder) leaves an existing target untouched and no temporary behind.
 */
class AtomicFile {
public:
    /** Writes `bytes` to `path`: empty on success, else why not (without the path), ending "; any old file is
     * unchanged" where one may exist. */
    static QString write(const QString& path, const QByteArray& bytes);
    /** The same; on failure false and, if `error` is set, "PATH: why". */
    static bool write(const QString& path, const QByteArray& bytes, QString* error);
    static bool write(const QString& path, std::string_view bytes, QString* error);
    static bool write(const std::filesystem::path& path, std::string_view bytes, std::string* error);
};

} // namespace vct::files
