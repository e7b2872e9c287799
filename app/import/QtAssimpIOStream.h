#pragma once

#include <assimp/IOStream.hpp>

#include <QFile>

#include <cstdint>

namespace vct::doc {

/** An Assimp stream over a QFile, so Assimp can read Qt resources (":/...") as well as plain files. */
class QtAssimpIOStream final : public Assimp::IOStream {
public:
    /** Names the file; nothing is opened until open(). */
    explicit QtAssimpIOStream(const QString& path);
    ~QtAssimpIOStream() override;

    /** Opens the file for reading or writing (Assimp's fopen-style mode); false if that failed. */
    bool open(const char* mode);

    size_t Read(void* buffer, size_t size, size_t count) override;
    size_t Write(const void* buffer, size_t size, size_t count) override;
    aiReturn Seek(size_t offset, aiOrigin origin) override;
    size_t Tell() const override;
    size_t FileSize() const override;
    void Flush() override;

private:
    /** Throws std::runtime_error once reads and seeks exceed any plausible parse of this file. */
    void countOperation();
    static constexpr std::uint64_t kOperationBudget = 4096;
    QFile m_file;
    std::uint64_t m_operations = 0;
    std::uint64_t m_budget = 0;
};

} // namespace vct::doc
