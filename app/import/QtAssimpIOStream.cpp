#include "QtAssimpIOStream.h"

#include <algorithm>

#include <cstring>
#include <stdexcept>

namespace vct::doc {

QtAssimpIOStream::QtAssimpIOStream(const QString& path)
    : m_file(path)
{
}

QtAssimpIOStream::~QtAssimpIOStream() = default;

bool QtAssimpIOStream::open(const char* mode)
{
    const bool write = std::strchr(mode, 'w') != nullptr || std::strchr(mode, 'a') != nullptr;
    return m_file.open(write ? QIODevice::WriteOnly : QIODevice::ReadOnly);
}

void QtAssimpIOStream::countOperation()
{
    // Some malformed files send Assimp 5.2's parsers into an endless read/seek loop that ignores failures
    // (found by fuzzing a PLY header). Past a budget no real parse reaches, throw: Assimp's importer catches
    // it and the import ends with this error instead of hanging the caller.
    if (m_budget == 0)
        m_budget
            = kOperationBudget + std::uint64_t(std::max<qint64>(m_file.size(), 0)); // one per byte at most
    if (++m_operations > m_budget)
        throw std::runtime_error(
            "the importer kept re-reading the file without progress; the file is probably damaged");
}

size_t QtAssimpIOStream::Read(void* buffer, size_t size, size_t count)
{
    countOperation();
    if (size == 0 || count == 0)
        return 0;
    // Assimp, like fread, counts whole elements; a partial trailing element is not one.
    const qint64 bytes = m_file.read(static_cast<char*>(buffer), qint64(size * count));
    return bytes <= 0 ? 0 : size_t(bytes) / size;
}

size_t QtAssimpIOStream::Write(const void* buffer, size_t size, size_t count)
{
    if (size == 0 || count == 0)
        return 0;
    const qint64 bytes = m_file.write(static_cast<const char*>(buffer), qint64(size * count));
    return bytes <= 0 ? 0 : size_t(bytes) / size;
}

aiReturn QtAssimpIOStream::Seek(size_t offset, aiOrigin origin)
{
    countOperation();
    qint64 target = 0;
    switch (origin) {
    case aiOrigin_SET:
        target = qint64(offset);
        break;
    case aiOrigin_CUR:
        target = m_file.pos() + qint64(offset);
        break;
    case aiOrigin_END:
        // Assimp passes the distance back from the end as an unsigned value.
        target = m_file.size() - qint64(offset);
        break;
    default:
        return aiReturn_FAILURE;
    }
    if (target < 0 || target > m_file.size())
        return aiReturn_FAILURE;
    return m_file.seek(target) ? aiReturn_SUCCESS : aiReturn_FAILURE;
}

size_t QtAssimpIOStream::Tell() const
{
    return size_t(m_file.pos());
}

size_t QtAssimpIOStream::FileSize() const
{
    return size_t(m_file.size());
}

void QtAssimpIOStream::Flush()
{
    m_file.flush();
}

} // namespace vct::doc
