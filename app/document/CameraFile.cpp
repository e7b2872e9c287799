#include "CameraFile.h"

#include "JsonFieldReader.h"
#include "files/AtomicFile.h"

#include <glm/geometric.hpp>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace vct::doc {

namespace {

QJsonArray toJson(const glm::vec3& v)
{
    return QJsonArray { double(v.x), double(v.y), double(v.z) };
}

constexpr int kMaxImageSide = 1 << 15;

} // namespace

bool CameraFile::read(const QString& path, CameraSetup& setup, QString* error, const glm::dvec3& origin)
{
    JsonFieldReader reader(path);
    reader.setOrigin(origin);
    QJsonObject root;
    CameraSetup result = setup;
    double fov = 0.0;
    bool ok = reader.readFile(path, &root)
        && reader.readPoint(
            root, QStringLiteral("position"), QStringLiteral("position"), &result.camera.position)
        && reader.readPoint(root, QStringLiteral("look_at"), QStringLiteral("look_at"), &result.camera.lookAt)
        && (!root.contains(QStringLiteral("up"))
            || reader.readVec3(root, QStringLiteral("up"), QStringLiteral("up"), &result.camera.up))
        && reader.readNumber(root, QStringLiteral("fov_y_deg"), QStringLiteral("fov_y_deg"), &fov)
        && reader.readInt(
            root, QStringLiteral("width"), QStringLiteral("width"), 1, kMaxImageSide, &result.width)
        && reader.readInt(
            root, QStringLiteral("height"), QStringLiteral("height"), 1, kMaxImageSide, &result.height);
    if (ok && !(fov > 0.0 && fov < 180.0))
        ok = reader.fail(
            QStringLiteral("fov_y_deg"), QStringLiteral("expected degrees in (0, 180), found %1").arg(fov));
    if (ok && glm::length(result.camera.lookAt - result.camera.position) <= 0.0f)
        ok = reader.fail(QStringLiteral("look_at"), QStringLiteral("must differ from position"));
    if (ok && glm::length(result.camera.up) <= 0.0f)
        ok = reader.fail(QStringLiteral("up"), QStringLiteral("must not be zero"));
    if (!ok) {
        if (error)
            *error = reader.error();
        return false;
    }
    result.camera.fovYDeg = float(fov);
    setup = result;
    return true;
}

bool CameraFile::write(const QString& path, const CameraSetup& setup, QString* error)
{
    QJsonObject root;
    root.insert(QStringLiteral("position"), toJson(setup.camera.position));
    root.insert(QStringLiteral("look_at"), toJson(setup.camera.lookAt));
    root.insert(QStringLiteral("up"), toJson(setup.camera.up));
    root.insert(QStringLiteral("fov_y_deg"), double(setup.camera.fovYDeg));
    root.insert(QStringLiteral("width"), setup.width);
    root.insert(QStringLiteral("height"), setup.height);

    return files::AtomicFile::write(path, QJsonDocument(root).toJson(QJsonDocument::Indented), error);
}

} // namespace vct::doc
