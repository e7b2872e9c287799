#include "ProjectFile.h"

#include "JsonFieldReader.h"
#include "files/AtomicFile.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>
#include <set>

namespace vct::doc {

namespace {

const QString kBuiltinPrefix = QStringLiteral("builtin:");
const QString kResourcePrefix = QStringLiteral(":/");
constexpr double kMaxId = 9007199254740992.0; // 2^53: the largest integer a JSON double holds exactly.

bool isModelPath(const QString& spec)
{
    return !spec.startsWith(kBuiltinPrefix) && !spec.startsWith(kResourcePrefix);
}

QJsonArray toArray(const glm::vec3& v)
{
    return QJsonArray { double(v.x), double(v.y), double(v.z) };
}

QString lightTypeName(LightType type)
{
    switch (type) {
    case LightType::Directional:
        return QStringLiteral("directional");
    case LightType::Spot:
        return QStringLiteral("spot");
    case LightType::Rect:
        return QStringLiteral("rect");
    case LightType::Disk:
        return QStringLiteral("disk");
    case LightType::Point:
        break;
    }
    return QStringLiteral("point");
}

/** Deepest nesting of arrays and objects, stopping early once it passes `limit` (no recursion, no parse). */
int nestingDepth(const QByteArray& bytes, int limit)
{
    int depth = 0;
    int deepest = 0;
    bool inString = false;
    bool escaped = false;
    for (const char c : bytes) {
        if (inString) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                inString = false;
            continue;
        }
        if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
            if (deepest > limit)
                break;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return deepest;
}

/** JsonFieldReader plus the shapes this format needs: arrays, objects, ids and float-range vectors. */
class ProjectReader : public JsonFieldReader {
public:
    using JsonFieldReader::JsonFieldReader;

    bool readArray(const QJsonObject& object, const QString& key, const QString& fieldPath, int maxSize,
        QJsonArray* value)
    {
        const QJsonValue v = object.value(key);
        if (!v.isArray())
            return fail(fieldPath, QStringLiteral("expected an array, found %1").arg(describe(v)));
        const QJsonArray array = v.toArray();
        if (array.size() > maxSize)
            return fail(fieldPath,
                QStringLiteral("has %1 entries; more than %2 are refused").arg(array.size()).arg(maxSize));
        *value = array;
        return true;
    }

    bool readObject(const QJsonValue& v, const QString& fieldPath, QJsonObject* value)
    {
        if (!v.isObject())
            return fail(fieldPath, QStringLiteral("expected an object, found %1").arg(describe(v)));
        *value = v.toObject();
        return true;
    }

    bool readId(const QJsonObject& object, const QString& key, const QString& fieldPath, quint64* value)
    {
        double d = 0.0;
        if (!readNumber(object, key, fieldPath, &d))
            return false;
        if (d != std::floor(d) || d < 1.0 || d > kMaxId)
            return fail(fieldPath, QStringLiteral("expected an integer id from 1 to 2^53, found %1").arg(d));
        *value = quint64(d);
        return true;
    }

    bool readFloat(
        const QJsonObject& object, const QString& key, const QString& fieldPath, float minimum, float* value)
    {
        double d = 0.0;
        if (!readNumber(object, key, fieldPath, &d))
            return false;
        if (!std::isfinite(float(d)))
            return fail(fieldPath, QStringLiteral("%1 is too large").arg(d));
        if (float(d) < minimum)
            return fail(fieldPath, QStringLiteral("must be %1 or more, found %2").arg(minimum).arg(d));
        *value = float(d);
        return true;
    }

    bool readFiniteVec3(
        const QJsonObject& object, const QString& key, const QString& fieldPath, glm::vec3* value)
    {
        glm::vec3 v(0.0f);
        if (!readVec3(object, key, fieldPath, &v))
            return false;
        // The JSON numbers are finite doubles, but may still overflow a float.
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
            return fail(fieldPath, QStringLiteral("a value is too large"));
        *value = v;
        return true;
    }

    static QString describe(const QJsonValue& v)
    {
        switch (v.type()) {
        case QJsonValue::Null:
            return QStringLiteral("null");
        case QJsonValue::Bool:
            return QStringLiteral("a boolean");
        case QJsonValue::Double:
            return QStringLiteral("a number");
        case QJsonValue::String:
            return QStringLiteral("a string");
        case QJsonValue::Array:
            return QStringLiteral("an array");
        case QJsonValue::Object:
            return QStringLiteral("an object");
        case QJsonValue::Undefined:
            break;
        }
        return QStringLiteral("nothing (missing)");
    }
};

/** "unit_scale": optional, 1 when absent; a built-in scene is in metres and takes no other. */
bool readUnitScale(
    ProjectReader& r, const QJsonObject& object, const QString& path, const QString& spec, float* unitScale)
{
    const QString field = path + QStringLiteral(".unit_scale");
    if (!object.contains(QStringLiteral("unit_scale")))
        return true;
    double d = 0.0;
    if (!r.readNumber(object, QStringLiteral("unit_scale"), field, &d))
        return false;
    const float scale = float(d);
    if (!(std::isfinite(scale) && scale > 0.0f))
        return r.fail(field,
            QStringLiteral(
                "expected metres per model unit, a number above 0 (0.01 for centimetres), found %1")
                .arg(d));
    if (spec.startsWith(kBuiltinPrefix) && scale != 1.0f)
        return r.fail(
            field, QStringLiteral("built-in scenes are in metres: only 1 is accepted, found %1").arg(d));
    *unitScale = scale;
    return true;
}

bool readSources(ProjectReader& r, const QJsonObject& root, const QString& modelRoot, DocumentState& out)
{
    QJsonArray array;
    if (!r.readArray(
            root, QStringLiteral("sources"), QStringLiteral("sources"), ProjectFile::kMaxSources, &array))
        return false;
    const QDir dir(modelRoot);
    for (qsizetype i = 0; i < array.size(); ++i) {
        const QString path = QStringLiteral("sources[%1]").arg(i);
        QJsonObject object;
        QString spec;
        if (!r.readObject(array[i], path, &object)
            || !r.readString(object, QStringLiteral("spec"), path + QStringLiteral(".spec"), &spec))
            return false;
        if (spec.isEmpty())
            return r.fail(path + QStringLiteral(".spec"), QStringLiteral("is empty"));
        SceneSource source { spec };
        if (!readUnitScale(r, object, path, spec, &source.unitScale))
            return false;
        if (isModelPath(spec)) {
            source.spec = QDir::cleanPath(dir.absoluteFilePath(spec));
            // A hostile project may name a device or FIFO ("/dev/zero" reads forever): only regular files.
            const QFileInfo model(source.spec);
            const QString resolved = QDir::toNativeSeparators(source.spec);
            if (model.exists() && !model.isFile())
                return r.fail(path + QStringLiteral(".spec"),
                    QStringLiteral("model '%1' is not a regular file").arg(resolved));
            // A relative path is the one way a project names a model it does not ship (a big model kept
            // outside the repository), so the message says where it looked and how to look elsewhere.
            if (!model.exists() && QDir::isRelativePath(spec))
                return r.fail(path + QStringLiteral(".spec"),
                    QStringLiteral("model file '%1' (%2.spec '%3') not found: give --scene-root DIR (or %4) "
                                   "naming the folder that holds %3")
                        .arg(resolved, path, spec, QLatin1String(ProjectFile::kModelRootVariable)));
            if (!model.exists())
                return r.fail(path + QStringLiteral(".spec"),
                    QStringLiteral("model file '%1' not found").arg(resolved));
        }
        out.sources.push_back(source);
    }
    return true;
}

/**
 * Each source's optional "placement" {translation, rotation_deg, scale, dynamic}: only where the project
 * takes its sources whole, since a listed node carries its own.
 */
bool readPlacements(ProjectReader& r, const QJsonObject& root, WholeSources& whole)
{
    const QJsonArray array = root.value(QStringLiteral("sources")).toArray();
    for (qsizetype i = 0; i < array.size(); ++i) {
        const QString path = QStringLiteral("sources[%1].placement").arg(i);
        NodeTransform placement;
        bool dynamic = false;
        const QJsonObject source = array[i].toObject();
        if (source.contains(QStringLiteral("placement"))) {
            if (!whole.used)
                return r.fail(path,
                    QStringLiteral("applies only to a project that lists no nodes: a listed "
                                   "node carries its own translation, rotation and scale"));
            QJsonObject o;
            if (!r.readObject(source.value(QStringLiteral("placement")), path, &o))
                return false;
            const QString prefix = path + QLatin1Char('.');
            if ((o.contains(QStringLiteral("translation"))
                    && !r.readFiniteVec3(o, "translation", prefix + "translation", &placement.translation))
                || (o.contains(QStringLiteral("rotation_deg"))
                    && !r.readFiniteVec3(o, "rotation_deg", prefix + "rotation_deg", &placement.rotationDeg))
                || (o.contains(QStringLiteral("scale"))
                    && !r.readFiniteVec3(o, "scale", prefix + "scale", &placement.scale))
                || (o.contains(QStringLiteral("dynamic"))
                    && !r.readBool(o, "dynamic", prefix + "dynamic", &dynamic)))
                return false;
            if (!(placement.scale.x > 0.0f && placement.scale.y > 0.0f && placement.scale.z > 0.0f))
                return r.fail(
                    prefix + QStringLiteral("scale"), QStringLiteral("expected three numbers above 0"));
        }
        whole.placement.push_back(placement);
        whole.dynamic.push_back(dynamic);
    }
    return true;
}

bool readMaterials(ProjectReader& r, const QJsonObject& root, DocumentState& out)
{
    QJsonArray array;
    if (!r.readArray(
            root, QStringLiteral("materials"), QStringLiteral("materials"), ProjectFile::kMaxNodes, &array))
        return false;
    for (qsizetype i = 0; i < array.size(); ++i) {
        const QString path = QStringLiteral("materials[%1].").arg(i);
        QJsonObject o;
        QString name;
        render::Material m;
        if (!r.readObject(array[i], path.chopped(1), &o) || !r.readString(o, "name", path + "name", &name)
            || !r.readFiniteVec3(o, "albedo", path + "albedo", &m.albedo)
            || !r.readFiniteVec3(o, "emission", path + "emission", &m.emission)
            || !r.readFiniteVec3(o, "specular", path + "specular", &m.specular)
            || !r.readFloat(o, "shininess", path + "shininess", 0.0f, &m.shininess)
            || !r.readInt(o, "albedo_texture", path + "albedo_texture", -1, INT_MAX, &m.albedoTexture)
            // Absent from projects saved before single-sided materials existed: both sides, as then.
            || (o.contains(QStringLiteral("double_sided"))
                && !r.readBool(o, "double_sided", path + "double_sided", &m.doubleSided)))
            return false;
        m.name = name.toStdString();
        out.materials.push_back(m);
    }
    return true;
}

bool readNodes(ProjectReader& r, const QJsonObject& root, DocumentState& out)
{
    QJsonArray array;
    if (!r.readArray(root, QStringLiteral("nodes"), QStringLiteral("nodes"), ProjectFile::kMaxNodes, &array))
        return false;
    const int lastSource = int(out.sources.size()) - 1;
    const int lastMaterial = int(out.materials.size()) - 1;
    for (qsizetype i = 0; i < array.size(); ++i) {
        const QString path = QStringLiteral("nodes[%1].").arg(i);
        QJsonObject o;
        SceneNode n;
        if (!r.readObject(array[i], path.chopped(1), &o) || !r.readId(o, "id", path + "id", &n.id)
            || !r.readString(o, "name", path + "name", &n.name)
            || !r.readInt(o, "source", path + "source", 0, lastSource, &n.source)
            || !r.readInt(o, "mesh", path + "mesh", 0, INT_MAX, &n.mesh)
            || !r.readInt(o, "material", path + "material", 0, lastMaterial, &n.material)
            || !r.readFiniteVec3(o, "translation", path + "translation", &n.transform.translation)
            || !r.readFiniteVec3(o, "rotation_deg", path + "rotation_deg", &n.transform.rotationDeg)
            || !r.readFiniteVec3(o, "scale", path + "scale", &n.transform.scale)
            || !r.readBool(o, "dynamic", path + "dynamic", &n.dynamic)
            || !r.readBool(o, "visible", path + "visible", &n.visible))
            return false;
        out.nodes.push_back(n);
    }
    return true;
}

/**
 * A rect's "size" ([width, height], metres) and optional "rotation_deg", or a disk's "diameter"; the same
 * names as in lights files. A surface light without area or facing nowhere emits nothing, so both are
 * refused.
 */
bool readSurfaceFields(ProjectReader& r, const QJsonObject& o, const QString& path, LightNode& l)
{
    constexpr float kLowest = std::numeric_limits<float>::lowest(); // any sign: the checks below say more
    if (l.direction == glm::vec3(0.0f))
        return r.fail(
            path + "direction", QStringLiteral("must not be zero for a %1 light").arg(lightTypeName(l.type)));
    if (l.type == LightType::Disk) {
        if (!r.readFloat(o, "diameter", path + "diameter", kLowest, &l.areaWidth))
            return false;
        if (!(l.areaWidth > 0.0f))
            return r.fail(
                path + "diameter", QStringLiteral("must be more than 0 m, found %1").arg(l.areaWidth));
        return true;
    }
    const QJsonValue size = o.value("size");
    const QJsonArray pair = size.toArray();
    if (!size.isArray() || pair.size() != 2)
        return r.fail(
            path + "size", QStringLiteral("expected an array of 2 numbers: width and height in metres"));
    const QJsonObject fields { { "width", pair[0] }, { "height", pair[1] } };
    if (!r.readFloat(fields, "width", path + "size", kLowest, &l.areaWidth)
        || !r.readFloat(fields, "height", path + "size", kLowest, &l.areaHeight))
        return false;
    if (!(l.areaWidth > 0.0f && l.areaHeight > 0.0f))
        return r.fail(path + "size",
            QStringLiteral("width and height must be more than 0 m, found %1 and %2")
                .arg(l.areaWidth)
                .arg(l.areaHeight));
    // Optional: hand-written projects may leave a rect square to the scene's axes.
    if (o.contains("rotation_deg")
        && !r.readFloat(o, "rotation_deg", path + "rotation_deg", kLowest, &l.areaRotationDeg))
        return false;
    return true;
}

bool readLights(ProjectReader& r, const QJsonObject& root, DocumentState& out)
{
    QJsonArray array;
    if (!r.readArray(
            root, QStringLiteral("lights"), QStringLiteral("lights"), ProjectFile::kMaxNodes, &array))
        return false;
    for (qsizetype i = 0; i < array.size(); ++i) {
        const QString path = QStringLiteral("lights[%1].").arg(i);
        QJsonObject o;
        QString type;
        LightNode l;
        if (!r.readObject(array[i], path.chopped(1), &o) || !r.readId(o, "id", path + "id", &l.id)
            || !r.readString(o, "name", path + "name", &l.name)
            || !r.readString(o, "type", path + "type", &type))
            return false;
        if (type == QStringLiteral("point"))
            l.type = LightType::Point;
        else if (type == QStringLiteral("directional"))
            l.type = LightType::Directional;
        else if (type == QStringLiteral("spot"))
            l.type = LightType::Spot;
        else if (type == QStringLiteral("rect"))
            l.type = LightType::Rect;
        else if (type == QStringLiteral("disk"))
            l.type = LightType::Disk;
        else
            return r.fail(path + "type",
                QStringLiteral(
                    "expected \"point\", \"spot\", \"directional\", \"rect\" or \"disk\", found \"%1\"")
                    .arg(type));
        if (!r.readFiniteVec3(o, "position", path + "position", &l.position)
            || !r.readFiniteVec3(o, "direction", path + "direction", &l.direction)
            || !r.readFiniteVec3(o, "color", path + "color", &l.color)
            || !r.readFloat(o, "intensity", path + "intensity", 0.0f, &l.intensity)
            || !r.readBool(o, "shadows", path + "shadows", &l.castsShadows))
            return false;
        if (l.type == LightType::Spot) {
            if (!r.readFloat(o, "inner_deg", path + "inner_deg", 0.0f, &l.spotInnerDeg)
                || !r.readFloat(o, "outer_deg", path + "outer_deg", 0.0f, &l.spotOuterDeg))
                return false;
            if (l.spotOuterDeg > 90.0f || l.spotInnerDeg > l.spotOuterDeg)
                return r.fail(path + "outer_deg",
                    QStringLiteral("a spot needs 0 <= inner_deg <= outer_deg <= 90, found %1 and %2")
                        .arg(l.spotInnerDeg)
                        .arg(l.spotOuterDeg));
        }
        if (l.isSurface() && !readSurfaceFields(r, o, path, l))
            return false;
        // Optional, 0 when absent: projects saved before lights had a size keep their hard shadows.
        if (l.isPointLike() && o.contains("radius")
            && !r.readFloat(o, "radius", path + "radius", 0.0f, &l.radius))
            return false;
        if (l.type == LightType::Directional && o.contains("angular_diameter_deg")) {
            if (!r.readFloat(
                    o, "angular_diameter_deg", path + "angular_diameter_deg", 0.0f, &l.angularDiameterDeg))
                return false;
            // As in lights files: half the sky or more is no longer a light from one direction.
            if (!(l.angularDiameterDeg < 90.0f))
                return r.fail(path + "angular_diameter_deg",
                    QStringLiteral("must be less than 90 degrees, found %1").arg(l.angularDiameterDeg));
        }
        out.lights.push_back(l);
    }
    return true;
}

/** The camera fields of `o`; `path` prefixes field names in errors ("camera.", "bookmarks[2]."). */
bool readCameraFields(ProjectReader& r, const QJsonObject& o, const QString& path, render::Camera* camera)
{
    render::Camera c;
    if (!r.readFiniteVec3(o, "position", path + "position", &c.position)
        || !r.readFiniteVec3(o, "look_at", path + "look_at", &c.lookAt)
        || !r.readFiniteVec3(o, "up", path + "up", &c.up)
        || !r.readFloat(o, "fov_y_deg", path + "fov_y_deg", 0.0f, &c.fovYDeg))
        return false;
    if (!(c.fovYDeg > 0.0f && c.fovYDeg < 180.0f))
        return r.fail(
            path + "fov_y_deg", QStringLiteral("must be between 0 and 180 degrees, found %1").arg(c.fovYDeg));
    // Optional: hand-written projects may leave the near plane at its default.
    if (r.hasField(o, "near_plane")) {
        if (!r.readFloat(o, "near_plane", path + "near_plane", 0.0f, &c.nearPlane))
            return false;
        if (!(c.nearPlane > 0.0f))
            return r.fail(path + "near_plane", QStringLiteral("must be greater than 0"));
    }
    *camera = c;
    return true;
}

bool readCamera(ProjectReader& r, const QJsonObject& root, DocumentState& out)
{
    QJsonObject o;
    return r.readObject(root.value("camera"), "camera", &o)
        && readCameraFields(r, o, QStringLiteral("camera."), &out.camera);
}

/** "bookmarks": optional (projects before bookmarks have none), each a name and camera fields. */
bool readBookmarks(ProjectReader& r, const QJsonObject& root, DocumentState& out)
{
    if (!root.contains(QStringLiteral("bookmarks")))
        return true;
    QJsonArray array;
    if (!r.readArray(
            root, QStringLiteral("bookmarks"), QStringLiteral("bookmarks"), ProjectFile::kMaxNodes, &array))
        return false;
    for (qsizetype i = 0; i < array.size(); ++i) {
        const QString path = QStringLiteral("bookmarks[%1].").arg(i);
        QJsonObject o;
        CameraBookmark bookmark;
        if (!r.readObject(array[i], path.chopped(1), &o)
            || !r.readString(o, "name", path + "name", &bookmark.name)
            || !readCameraFields(r, o, path, &bookmark.camera))
            return false;
        out.bookmarks.push_back(bookmark);
    }
    return true;
}

QJsonObject cameraJson(const render::Camera& c)
{
    return QJsonObject { { "position", toArray(c.position) }, { "look_at", toArray(c.lookAt) },
        { "up", toArray(c.up) }, { "fov_y_deg", double(c.fovYDeg) }, { "near_plane", double(c.nearPlane) } };
}

bool readSettings(ProjectReader& r, const QJsonObject& root, DocumentState& out)
{
    QJsonObject o;
    if (!r.readObject(root.value("settings"), "settings", &o))
        return false;
    render::RenderSettings settings;
    for (auto it = o.begin(); it != o.end(); ++it) {
        const QString path = QStringLiteral("settings.%1").arg(it.key());
        if (!it.value().isString())
            return r.fail(path,
                QStringLiteral("expected the value as a string, found %1")
                    .arg(ProjectReader::describe(it.value())));
        const std::string problem = settings.set(it.key().toStdString(), it.value().toString().toStdString());
        if (!problem.empty())
            return r.fail(path, QString::fromStdString(problem));
    }
    out.settings = settings;
    return true;
}

bool readIds(ProjectReader& r, const QJsonObject& root, DocumentState& out)
{
    if (!r.readId(root, "next_id", "next_id", &out.nextId))
        return false;
    std::set<quint64> seen;
    auto check = [&](quint64 id, const QString& path) {
        if (!seen.insert(id).second)
            return r.fail(path, QStringLiteral("id %1 is used twice").arg(id));
        if (id >= out.nextId)
            return r.fail(QStringLiteral("next_id"),
                QStringLiteral("must be greater than every id, but %1 is %2").arg(path).arg(id));
        return true;
    };
    for (std::size_t i = 0; i < out.nodes.size(); ++i)
        if (!check(out.nodes[i].id, QStringLiteral("nodes[%1].id").arg(i)))
            return false;
    for (std::size_t i = 0; i < out.lights.size(); ++i)
        if (!check(out.lights[i].id, QStringLiteral("lights[%1].id").arg(i)))
            return false;
    return true;
}

} // namespace

QByteArray ProjectFile::toJson(const DocumentState& state, const QString& projectDir)
{
    const QDir dir(projectDir);
    QJsonArray sources;
    for (const SceneSource& source : state.sources) {
        const QString spec = isModelPath(source.spec) ? dir.relativeFilePath(source.spec) : source.spec;
        QJsonObject object { { "spec", spec } };
        // Only when needed: files of models in metres stay as they were before the field existed.
        if (source.unitScale != 1.0f)
            object["unit_scale"] = double(source.unitScale);
        sources.append(object);
    }
    QJsonArray materials;
    for (const render::Material& m : state.materials)
        materials.append(QJsonObject { { "name", QString::fromStdString(m.name) },
            { "albedo", toArray(m.albedo) }, { "emission", toArray(m.emission) },
            { "specular", toArray(m.specular) }, { "shininess", double(m.shininess) },
            { "albedo_texture", m.albedoTexture }, { "double_sided", m.doubleSided } });
    QJsonArray nodes;
    for (const SceneNode& n : state.nodes)
        nodes.append(QJsonObject { { "id", qint64(n.id) }, { "name", n.name }, { "source", n.source },
            { "mesh", n.mesh }, { "material", n.material },
            { "translation", toArray(n.transform.translation) },
            { "rotation_deg", toArray(n.transform.rotationDeg) }, { "scale", toArray(n.transform.scale) },
            { "dynamic", n.dynamic }, { "visible", n.visible } });
    QJsonArray lights;
    for (const LightNode& l : state.lights) {
        QJsonObject light { { "id", qint64(l.id) }, { "name", l.name }, { "type", lightTypeName(l.type) },
            { "position", toArray(l.position) }, { "direction", toArray(l.direction) },
            { "color", toArray(l.color) }, { "intensity", double(l.intensity) },
            { "shadows", l.castsShadows } };
        if (l.isPointLike())
            light["radius"] = double(l.radius);
        else if (l.type == LightType::Directional)
            light["angular_diameter_deg"] = double(l.angularDiameterDeg);
        if (l.type == LightType::Spot) {
            light["inner_deg"] = double(l.spotInnerDeg);
            light["outer_deg"] = double(l.spotOuterDeg);
        }
        if (l.type == LightType::Rect) {
            light["size"] = QJsonArray { double(l.areaWidth), double(l.areaHeight) };
            light["rotation_deg"] = double(l.areaRotationDeg);
        } else if (l.type == LightType::Disk) {
            light["diameter"] = double(l.areaWidth);
        }
        lights.append(light);
    }
    const QJsonObject camera = cameraJson(state.camera);
    QJsonArray bookmarks;
    for (const CameraBookmark& bookmark : state.bookmarks) {
        QJsonObject entry = cameraJson(bookmark.camera);
        entry.insert(QStringLiteral("name"), bookmark.name);
        bookmarks.append(entry);
    }
    QJsonObject settings;
    for (const auto& row : state.settings.describe())
        settings.insert(QString::fromStdString(row[0]), QString::fromStdString(row[1]));

    const QJsonObject root { { "format", QString::fromLatin1(kFormat) }, { "version", kVersion },
        { "sources", sources }, { "materials", materials }, { "nodes", nodes }, { "lights", lights },
        { "camera", camera }, { "bookmarks", bookmarks }, { "settings", settings },
        { "next_id", qint64(state.nextId) } };
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

bool ProjectFile::fromJson(const QByteArray& json, const QString& projectDir, const QString& fileName,
    DocumentState* state, QString* error, WholeSources* wholeSources)
{
    ProjectReader r(fileName);
    auto failed = [&] {
        if (error)
            *error = r.error();
        return false;
    };
    auto fail = [&](const QString& fieldPath, const QString& problem) {
        r.fail(fieldPath, problem);
        return failed();
    };
    if (!json.isValidUtf8())
        return fail(QString(), QStringLiteral("is not valid UTF-8 text"));
    if (nestingDepth(json, kMaxNesting) > kMaxNesting)
        return fail(
            QString(), QStringLiteral("arrays or objects nest deeper than %1 levels").arg(kMaxNesting));
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return fail(QString(),
            QStringLiteral("invalid JSON at offset %1: %2")
                .arg(parseError.offset)
                .arg(parseError.errorString()));
    if (!document.isObject())
        return fail(QString(), QStringLiteral("expected a JSON object at the top level"));
    const QJsonObject root = document.object();

    QString format;
    if (!r.readString(root, "format", "format", &format))
        return failed();
    if (format != QLatin1String(kFormat))
        return fail("format",
            QStringLiteral("expected \"%1\", found \"%2\": not a VCT Studio project")
                .arg(QLatin1String(kFormat), format));
    int version = 0;
    if (!r.readInt(root, "version", "version", 1, INT_MAX, &version))
        return failed();
    // Checked before anything else: a newer file may be laid out differently.
    if (version > kVersion)
        return fail("version",
            QStringLiteral("was saved by a newer VCT Studio (version %1); this one reads version %2")
                .arg(version)
                .arg(kVersion));

    // Both or neither: nodes index materials, so one without the other cannot be what the author meant.
    const bool hasNodes = root.contains(QStringLiteral("nodes"));
    const bool hasMaterials = root.contains(QStringLiteral("materials"));
    if (hasNodes != hasMaterials)
        return fail(hasNodes ? QStringLiteral("materials") : QStringLiteral("nodes"),
            QStringLiteral(
                "missing: a project lists both nodes and materials, or neither to take every source "
                "whole"));

    DocumentState result;
    WholeSources whole;
    whole.used = !hasNodes;
    if (!readSources(r, root, projectDir, result) || !readPlacements(r, root, whole)
        || (hasMaterials && (!readMaterials(r, root, result) || !readNodes(r, root, result)))
        || !readLights(r, root, result) || !readCamera(r, root, result) || !readBookmarks(r, root, result)
        || !readSettings(r, root, result) || !readIds(r, root, result))
        return failed();
    *state = std::move(result);
    if (wholeSources)
        *wholeSources = std::move(whole);
    return true;
}

QString ProjectFile::modelDir(const QString& projectPath, const QString& modelRoot)
{
    return modelRoot.isEmpty() ? QFileInfo(projectPath).absolutePath()
                               : QDir::cleanPath(QFileInfo(modelRoot).absoluteFilePath());
}

bool ProjectFile::load(const QString& path, DocumentState* state, QString* error, const QString& modelRoot,
    WholeSources* wholeSources)
{
    const QString name = QDir::toNativeSeparators(path);
    auto fail = [&](const QString& problem) {
        if (error)
            *error = QStringLiteral("%1: %2").arg(name, problem);
        return false;
    };
    const QFileInfo info(path);
    if (!info.exists())
        return fail(QStringLiteral("file not found"));
    if (info.isDir())
        return fail(QStringLiteral("is a folder, not a project file"));
    if (info.size() > kMaxFileBytes)
        return fail(QStringLiteral("is %1 bytes; project files over %2 MiB are refused")
                        .arg(info.size())
                        .arg(kMaxFileBytes / (1024 * 1024)));
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return fail(QStringLiteral("cannot open: %1").arg(file.errorString()));
    // Bounded read: the size above may not be the whole story (a file growing, a special file).
    const QByteArray bytes = file.read(kMaxFileBytes + 1);
    if (file.error() != QFileDevice::NoError)
        return fail(QStringLiteral("cannot read: %1").arg(file.errorString()));
    if (bytes.size() > kMaxFileBytes)
        return fail(QStringLiteral("is larger than %1 MiB; refused").arg(kMaxFileBytes / (1024 * 1024)));
    return fromJson(bytes, modelDir(path, modelRoot), name, state, error, wholeSources);
}

bool ProjectFile::save(
    const QString& path, const DocumentState& state, QString* error, const QString& modelRoot)
{
    const QString name = QDir::toNativeSeparators(path);
    auto fail = [&](const QString& problem) {
        if (error)
            *error = QStringLiteral("%1: %2").arg(name, problem);
        return false;
    };
    const QFileInfo info(path);
    if (!info.absoluteDir().exists())
        return fail(QStringLiteral("cannot save: the folder %1 does not exist")
                        .arg(QDir::toNativeSeparators(info.absolutePath())));
    if (info.isDir())
        return fail(QStringLiteral("cannot save: a folder of that name is in the way"));
    const QByteArray bytes = toJson(state, modelDir(path, modelRoot));
    if (const QString problem = files::AtomicFile::write(path, bytes); !problem.isEmpty())
        return fail(QStringLiteral("cannot save: ") + problem);
    return true;
}

} // namespace vct::doc
