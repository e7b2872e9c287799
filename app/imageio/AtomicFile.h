#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace vct::io {

/**
 * Replaces a file's contents all at once: the bytes go to a temporary file in the target's directory,
 * which is renamed over the target only when every byte is written. A failed write leaves an existing
 * target untouched and no temporary behind.
 */
class AtomicFile {
public:
    /** Writes @p bytes to @p path. On failure returns false and, if @p error is set, a message naming the
     * file. */
    static bool write(const std::filesystem::path& path, std::string_view bytes, std::string* error);
};

} // namespace vct::io
