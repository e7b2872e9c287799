#pragma once

#include <glm/ext/vector_double3.hpp>
#include <glm/vec3.hpp>

#include <QJsonObject>
#include <QString>

namespace vct::doc {

/**
 * Reads typed, finite fields out of a JSON object and, on the first failure, builds an error message that
 * names the file and the field path ("cornell.camera.json: field 'lights[1].position': expected 3 finite
 * numbers"). Each read returns false on failure and leaves the output untouched.
 */
class JsonFieldReader {
public:
    /** `fileName` is used in messages only. */
    explicit JsonFieldReader(QString fileName);

    /** Parses a whole file into an object; false (with an error) when it is unreadable or not a JSON object.
     */
    bool readFile(const QString& path, QJsonObject* root);

    bool hasField(const QJsonObject& object, const QString& key) const;
    /** A finite number. `fieldPath` is the name shown in errors, e.g. "lights[0].intensity". */
    bool readNumber(const QJsonObject& object, const QString& key, const QString& fieldPath, double* value);
    /** An integer in [minimum, maximum]. */
    bool readInt(const QJsonObject& object, const QString& key, const QString& fieldPath, int minimum,
        int maximum, int* value);
    bool readBool(const QJsonObject& object, const QString& key, const QString& fieldPath, bool* value);
    bool readString(const QJsonObject& object, const QString& key, const QString& fieldPath, QString* value);
    /** An array of exactly three finite numbers. */
    bool readVec3(const QJsonObject& object, const QString& key, const QString& fieldPath, glm::vec3* value);
    /**
     * A point: three finite numbers, less the origin (setOrigin), subtracted in double precision before the
     * result becomes float, and finite as floats. A scene far from the world's origin is read this way so
     * that its lights and camera keep the precision its geometry has once it is rebased (SceneRebase).
     */
    bool readPoint(const QJsonObject& object, const QString& key, const QString& fieldPath, glm::vec3* value);
    /** The world position that readPoint subtracts; zero unless set. */
    void setOrigin(const glm::dvec3& origin) { m_origin = origin; }

    /** Records an error about `fieldPath` (or the whole file if empty); always returns false. */
    bool fail(const QString& fieldPath, const QString& problem);
    const QString& error() const { return m_error; }

private:
    bool readDoubles(
        const QJsonObject& object, const QString& key, const QString& fieldPath, glm::dvec3* value);

    QString m_fileName;
    QString m_error;
    glm::dvec3 m_origin { 0.0 };
};

} // namespace vct::doc
