#include "LightsFile.h"

#include "JsonFieldReader.h"

#include <glm/geometric.hpp>

#include <QJsonArray>
#include <QJsonObject>

#include <cmath>
#include <vector>

namespace vct::doc {

namespace {

bool isNonNegative(const glm::vec3& v)
{
    return v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f;
}

// The JSON numbers are finite doubles, but may still overflow a float.
bool isFinite(const glm::vec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/** A vec3 that is finite as floats too. */
bool readFiniteVec3(JsonFieldReader& reader, const QJsonObject& object, const QString& key,
    const QString& fieldPath, glm::vec3* value)
{
    glm::vec3 v(0.0f);
    if (!reader.readVec3(object, key, fieldPath, &v))
        return false;
    if (!isFinite(v))
        return reader.fail(fieldPath, QStringLiteral("a value is too large"));
    *value = v;
    return true;
}

/** A float length in metres, more than zero. */
bool readPositiveLength(JsonFieldReader& reader, double value, const QString& fieldPath, float* length)
{
    if (!std::isfinite(float(value)))
        return reader.fail(fieldPath, QStringLiteral("%1 is too large").arg(value));
    if (!(float(value) > 0.0f))
        return reader.fail(fieldPath, QStringLiteral("must be more than 0 m, found %1").arg(value));
    *length = float(value);
    return true;
}

/**
 * An optional light size, 0 when absent: files written before lights had a size keep their hard shadows.
 * A negative size has no meaning and one too large for a float would reach the shaders as infinity.
 */
bool readOptionalSize(JsonFieldReader& reader, const QJsonObject& light, const QString& key,
    const QString& fieldPath, float* size)
{
    if (!light.contains(key))
        return true;
    double value = 0.0;
    if (!reader.readNumber(light, key, fieldPath, &value))
        return false;
    if (!std::isfinite(float(value)))
        return reader.fail(fieldPath, QStringLiteral("%1 is too large").arg(value));
    if (value < 0.0)
        return reader.fail(fieldPath, QStringLiteral("must not be negative, found %1").arg(value));
    *size = float(value);
    return true;
}

/**
 * The fields of a "rect" or "disk" light after "type" and "shadows": position, direction, its size, rotation
 * and radiance. False with the reader's error on the first bad field.
 */
bool readSurfaceLight(JsonFieldReader& reader, const QJsonObject& light, const QString& prefix, bool rect,
    render::SurfaceLight* surface)
{
    surface->shape = rect ? render::SurfaceLight::Shape::Rectangle : render::SurfaceLight::Shape::Disk;
    if (!reader.readPoint(
            light, QStringLiteral("position"), prefix + QStringLiteral(".position"), &surface->centre)
        || !readFiniteVec3(reader, light, QStringLiteral("direction"), prefix + QStringLiteral(".direction"),
            &surface->direction))
        return false;
    if (!(glm::length(surface->direction) > 0.0f))
        return reader.fail(prefix + QStringLiteral(".direction"), QStringLiteral("must not be zero"));
    if (rect) {
        const QString sizePath = prefix + QStringLiteral(".size");
        const QJsonValue size = light.value(QStringLiteral("size"));
        const QJsonArray pair = size.toArray();
        if (!size.isArray() || pair.size() != 2)
            return reader.fail(
                sizePath, QStringLiteral("expected an array of 2 numbers: width and height in metres"));
        for (int i = 0; i < 2; ++i)
            if (!pair[i].isDouble() || !std::isfinite(pair[i].toDouble()))
                return reader.fail(sizePath, QStringLiteral("element %1 is not a finite number").arg(i));
        if (!readPositiveLength(reader, pair[0].toDouble(), sizePath, &surface->width)
            || !readPositiveLength(reader, pair[1].toDouble(), sizePath, &surface->height))
            return false;
        // Optional: most rectangles line up with the scene's horizontal axis.
        if (light.contains(QStringLiteral("rotation_deg"))) {
            double rotation = 0.0;
            if (!reader.readNumber(light, QStringLiteral("rotation_deg"),
                    prefix + QStringLiteral(".rotation_deg"), &rotation))
                return false;
            if (!std::isfinite(float(rotation)))
                return reader.fail(prefix + QStringLiteral(".rotation_deg"),
                    QStringLiteral("%1 is too large").arg(rotation));
            surface->rotationDeg = float(rotation);
        }
    } else {
        double diameter = 0.0;
        if (!reader.readNumber(
                light, QStringLiteral("diameter"), prefix + QStringLiteral(".diameter"), &diameter)
            || !readPositiveLength(reader, diameter, prefix + QStringLiteral(".diameter"), &surface->width))
            return false;
    }
    if (!readFiniteVec3(reader, light, QStringLiteral("radiance"), prefix + QStringLiteral(".radiance"),
            &surface->radiance))
        return false;
    if (!isNonNegative(surface->radiance))
        return reader.fail(prefix + QStringLiteral(".radiance"), QStringLiteral("must not be negative"));
    return true;
}

} // namespace

bool LightsFile::read(const QString& path, render::Scene& scene, QString* error, const glm::dvec3& origin)
{
    JsonFieldReader reader(path);
    reader.setOrigin(origin);
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
    std::vector<render::SurfaceLight> surfaces;
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
            if (!reader.readPoint(
                    light, QStringLiteral("position"), prefix + QStringLiteral(".position"), &point.position)
                || !reader.readVec3(light, QStringLiteral("intensity"), prefix + QStringLiteral(".intensity"),
                    &point.intensity))
                return failed();
            if (!isNonNegative(point.intensity)) {
                reader.fail(prefix + QStringLiteral(".intensity"), QStringLiteral("must not be negative"));
                return failed();
            }
            if (!readOptionalSize(reader, light, QStringLiteral("radius"), prefix + QStringLiteral(".radius"),
                    &point.radius))
                return failed();
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
            const QString diameterPath = prefix + QStringLiteral(".angular_diameter_deg");
            if (!readOptionalSize(reader, light, QStringLiteral("angular_diameter_deg"), diameterPath,
                    &directional.angularDiameterDeg))
                return failed();
            // A disk 90 degrees or more across is half the sky or more: no longer a light from one direction.
            if (!(directional.angularDiameterDeg < 90.0f)) {
                reader.fail(diameterPath,
                    QStringLiteral("must be less than 90 degrees, found %1")
                        .arg(directional.angularDiameterDeg));
                return failed();
            }
            directionals.push_back(directional);
        } else if (type == QLatin1String("rect") || type == QLatin1String("disk")) {
            render::SurfaceLight surface;
            surface.castsShadows = castsShadows;
            if (!readSurfaceLight(reader, light, prefix, type == QLatin1String("rect"), &surface))
                return failed();
            surfaces.push_back(surface);
        } else {
            reader.fail(prefix + QStringLiteral(".type"),
                QStringLiteral("unknown light type \"%1\" (expected \"point\", \"spot\", \"directional\", "
                               "\"rect\" or \"disk\")")
                    .arg(type));
            return failed();
        }
    }

    scene.pointLights.insert(scene.pointLights.end(), points.begin(), points.end());
    scene.directionalLights.insert(scene.directionalLights.end(), directionals.begin(), directionals.end());
    scene.surfaceLights.insert(scene.surfaceLights.end(), surfaces.begin(), surfaces.end());
    return true;
}

} // namespace vct::doc
