#pragma once

#include <assimp/IOSystem.hpp>

#include <QString>
#include <QStringList>

namespace vct::doc {

/**
 * Lets Assimp open files through QFile, so models embedded as Qt resources (":/scenes/...") load, including
 * the files they reference relative to themselves (an OBJ's mtllib, a glTF's buffers). Paths are UTF-8.
 *
 * A model names the files it needs, and a model from anywhere may name anything: "../../.ssh/id_rsa",
 * "/dev/zero" (reads forever), a FIFO (blocks forever). Only regular files inside the model's own folder
 * (symbolic links resolved) are opened; every refusal is recorded so the import can say what was left out.
 */
class QtAssimpIOSystem final : public Assimp::IOSystem {
public:
    /** @p modelPath is the file being imported; its folder bounds what may be opened. */
    QtAssimpIOSystem(const QString& modelPath, QStringList* refusals);
    ~QtAssimpIOSystem() override;

    bool Exists(const char* path) const override;
    char getOsSeparator() const override;
    Assimp::IOStream* Open(const char* path, const char* mode = "rb") override;
    void Close(Assimp::IOStream* stream) override;

    /** Empty when @p path may be opened (or does not exist), else why not; textures follow the same rule. */
    QString refusalReason(const QString& path) const;

private:
    QString m_root; ///< The model's folder, canonical, with a trailing '/'.
    QStringList* m_refusals; ///< Owned by the caller, who reports them.
};

} // namespace vct::doc
