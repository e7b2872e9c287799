#include "LightsFile.h"

#include "JsonFieldReader.h"

#include <glm/geometric.hpp>

#include <QJsonArray>
#include <QJsonObject>

#include <vector>

namespace vct::doc {

namespace {

bool isNonNegative(const glm::vec3& v)
{
    return v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f;
}

} // namespace

bool LightsFile::read(const QString& path, render::Scene& scene, QString* error)
{
    JsonFieldReader reader(path);
    auto failed = [&]() {
        if (error)
            *error = reader.error();
        return false;
    };

    QJsonObject root;
    if (!reader.readFile(path, &root))
        return failed();
    bool shadows = true;
    if (root.contains(QStringLiteral("shadows"))
        && !reader.readBool(root, QStringLiteral("shadows"), QStringLiteral("shadows"), &shadows))
        return failed();
    const QJsonValue lightsValue = root.value(QStringLiteral("lights"));
    if (!lightsValue.isArray()) {
        reader.fail(QStringLiteral("lights"), QStringLiteral("expected an array of lights"));
        return failed();
    }

    std::vector<render::PointLight> points;
    std::vector<render::DirectionalLight> directionals;
    const QJsonArray lights = lightsValue.toArray();
    for (int i = 0; i < lights.size(); ++i) {
        const QString prefix = QStringLiteral("lights[%1]").arg(i);
        if (!lights[i].isObject()) {
            reader.fail(prefix, QStringLiteral("expected an object"));
            return failed();
        }
        const QJsonObject light = lights[i].toObject();
        QString type;
        if (!reader.readString(light, QStringLiteral("type"), prefix + QStringLiteral(".type"), &type))
            return failed();
        bool castsShadows = shadows;
        if (light.contains(QStringLiteral("shadows"))
            && !reader.readBool(
                light, QStringLiteral("shadows"), prefix + QStringLiteral(".shadows"), &castsShadows))
            return failed();

        if (type == QLatin1String("point") || type == QLatin1String("spot")) {
            render::PointLight point;
            point.castsShadows = castsShadows;
            if (!reader.readVec3(
                    light, QStringLiteral("position"), prefix + QStringLiteral(".position"), &point.position)
                || !reader.readVec3(light, QStringLiteral("intensity"), prefix + QStringLiteral(".intensity"),
                    &point.intensity))
                return failed();
            if (!isNonNegative(point.intensity)) {
                reader.fail(prefix + QStringLiteral(".intensity"), QStringLiteral("must not be negative"));
                return failed();
            }
            if (type == QLatin1String("spot")) {
                double inner = 0.0, outer = 0.0;
                if (!reader.readVec3(light, QStringLiteral("direction"),
                        prefix + QStringLiteral(".direction"), &point.spotDirection)
                    || !reader.readNumber(
                        light, QStringLiteral("inner_deg"), prefix + QStringLiteral(".inner_deg"), &inner)
                    || !reader.readNumber(
                        light, QStringLiteral("outer_deg"), prefix + QStringLiteral(".outer_deg"), &outer))
                    return failed();
                if (!(glm::length(point.spotDirection) > 0.0f)) {
                    reader.fail(prefix + QStringLiteral(".direction"), QStringLiteral("must not be zero"));
                    return failed();
                }
                if (!(inner >= 0.0 && inner <= outer && outer <= 90.0)) {
                    reader.fail(prefix + QStringLiteral(".outer_deg"),
                        QStringLiteral("a spot needs 0 <= inner_deg <= outer_deg <= 90, found %1 and %2")
                            .arg(inner)
                            .arg(outer));
                    return failed();
                }
                point.spotDirection = glm::normalize(point.spotDirection);
                point.spotInnerDeg = float(inner);
                point.spotOuterDeg = float(outer);
            }
            points.push_back(point);
        } else if (type == QLatin1String("directional")) {
            render::DirectionalLight directional;
            directional.castsShadows = castsShadows;
            if (!reader.readVec3(light, QStringLiteral("direction"), prefix + QStringLiteral(".direction"),
                    &directional.direction)
                || !reader.readVec3(light, QStringLiteral("irradiance"),
                    prefix + QStringLiteral(".irradiance"), &directional.irradiance))
                return failed();
            if (glm::length(directional.direction) <= 0.0f) {
                reader.fail(prefix + QStringLiteral(".direction"), QStringLiteral("must not be zero"));
                return failed();
            }
            if (!isNonNegative(directional.irradiance)) {
                reader.fail(prefix + QStringLiteral(".irradiance"), QStringLiteral("must not be negative"));
                return failed();
            }
            directionals.push_back(directional);
        } else {
            reader.fail(prefix + QStringLiteral(".type"),
                QStringLiteral("unknown light type \"%1\" (expected \"point\", \"spot\" or \"directional\")")
                    .arg(type));
            return failed();
        }
    }

    scene.pointLights.insert(scene.pointLights.end(), points.begin(), points.end());
    scene.directionalLights.insert(scene.directionalLights.end(), directionals.begin(), directionals.end());
    return true;
}

} // namespace vct::doc
