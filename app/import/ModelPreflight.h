#pragma once

#include <QByteArray>
#include <QString>

namespace vct::doc {

/**
 * Checks a model file's bytes before Assimp sees them. Assimp 5.2 trusts headers: a damaged PLY header made
 * it read past its buffer (tests/fuzz/corpus/model/regression-ply-header-overread.ply), a PLY that promises
 * 2^31 vertices made it allocate for them, and its recursive JSON parser overflows the stack on deeply nested
 * glTF. Each check refuses such a file with a message that says what is wrong, so the importer can fail
 * cleanly instead.
 */
class ModelPreflight {
public:
    /** Deepest JSON nesting a glTF may use; real files stay below 10, the stack overflows in the thousands.
     */
    static constexpr int kMaxJsonDepth = 64;
    /** Bytes of a PLY header; real headers are a few hundred bytes, Assimp reads header lines unbounded. */
    static constexpr int kMaxPlyHeaderBytes = 64 * 1024;
    /** Models larger than this are refused before any parsing (1 GiB; the atrium's OBJ would be ~5 MB). */
    static constexpr qint64 kMaxModelBytes = qint64(1) << 30;

    /**
     * Checks the file at @p path (whose name picks the format, as in Assimp; the content's magic bytes
     * too). Returns an empty string when it may go to Assimp, else the problem, without the file name.
     */
    static QString check(const QString& path);

    /** The PLY header rules on @p bytes (the whole file or at least its header); empty when acceptable. */
    static QString checkPly(const QByteArray& bytes, qint64 fileSize);
    /** Nesting depth and bracket balance of a JSON text (a .gltf or a GLB's JSON chunk); empty when fine. */
    static QString checkJsonNesting(const QByteArray& json);
};

} // namespace vct::doc
