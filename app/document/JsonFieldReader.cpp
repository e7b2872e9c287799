#include "JsonFieldReader.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonParseError>

#include <cmath>
#include <utility>

namespace vct::doc {

namespace {

QString typeName(const QJsonValue& value)
{
    switch (value.type()) {
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
    return QStringLiteral("missing");
}

} // namespace

JsonFieldReader::JsonFieldReader(QString fileName)
    : m_fileName(std::move(fileName))
{
}

bool JsonFieldReader::readFile(const QString& path, QJsonObject* root)
{
    QFile file(path);
    if (!file.exists())
        return fail(QString(), QStringLiteral("file not found"));
    if (!file.open(QIODevice::ReadOnly))
        return fail(QString(), QStringLiteral("cannot open: %1").arg(file.errorString()));
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(file.readAll(), &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return fail(QString(),
            QStringLiteral("invalid JSON at offset %1: %2")
                .arg(parseError.offset)
                .arg(parseError.errorString()));
    if (!document.isObject())
        return fail(QString(), QStringLiteral("expected a JSON object at the top level"));
    *root = document.object();
    return true;
}

bool JsonFieldReader::hasField(const QJsonObject& object, const QString& key) const
{
    return object.contains(key);
}

bool JsonFieldReader::readNumber(
    const QJsonObject& object, const QString& key, const QString& fieldPath, double* value)
{
    const QJsonValue v = object.value(key);
    if (!v.isDouble())
        return fail(fieldPath, QStringLiteral("expected a number, found %1").arg(typeName(v)));
    const double d = v.toDouble();
    if (!std::isfinite(d))
        return fail(fieldPath, QStringLiteral("expected a finite number"));
    *value = d;
    return true;
}

bool JsonFieldReader::readInt(const QJsonObject& object, const QString& key, const QString& fieldPath,
    int minimum, int maximum, int* value)
{
    double d = 0.0;
    if (!readNumber(object, key, fieldPath, &d))
        return false;
    if (d != std::floor(d) || d < minimum || d > maximum)
        return fail(fieldPath,
            QStringLiteral("expected an integer in [%1, %2], found %3").arg(minimum).arg(maximum).arg(d));
    *value = int(d);
    return true;
}

bool JsonFieldReader::readBool(
    const QJsonObject& object, const QString& key, const QString& fieldPath, bool* value)
{
    const QJsonValue v = object.value(key);
    if (!v.isBool())
        return fail(fieldPath, QStringLiteral("expected true or false, found %1").arg(typeName(v)));
    *value = v.toBool();
    return true;
}

bool JsonFieldReader::readString(
    const QJsonObject& object, const QString& key, const QString& fieldPath, QString* value)
{
    const QJsonValue v = object.value(key);
    if (!v.isString())
        return fail(fieldPath, QStringLiteral("expected a string, found %1").arg(typeName(v)));
    *value = v.toString();
    return true;
}

bool JsonFieldReader::readDoubles(
    const QJsonObject& object, const QString& key, const QString& fieldPath, glm::dvec3* value)
{
    const QJsonValue v = object.value(key);
    const QJsonArray array = v.toArray();
    if (!v.isArray() || array.size() != 3)
        return fail(fieldPath,
            QStringLiteral("expected an array of 3 numbers, found %1")
                .arg(v.isArray() ? QStringLiteral("%1 elements").arg(array.size()) : typeName(v)));
    for (int i = 0; i < 3; ++i) {
        if (!array[i].isDouble() || !std::isfinite(array[i].toDouble()))
            return fail(fieldPath, QStringLiteral("element %1 is not a finite number").arg(i));
        (*value)[i] = array[i].toDouble();
    }
    return true;
}

bool JsonFieldReader::readVec3(
    const QJsonObject& object, const QString& key, const QString& fieldPath, glm::vec3* value)
{
    glm::dvec3 result(0.0);
    if (!readDoubles(object, key, fieldPath, &result))
        return false;
    *value = glm::vec3(result);
    return true;
}

bool JsonFieldReader::readPoint(
    const QJsonObject& object, const QString& key, const QString& fieldPath, glm::vec3* value)
{
    glm::dvec3 result(0.0);
    if (!readDoubles(object, key, fieldPath, &result))
        return false;
    const glm::vec3 local(result - m_origin);
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(local[i]))
            return fail(fieldPath, QStringLiteral("element %1 is too large").arg(i));
    *value = local;
    return true;
}

bool JsonFieldReader::fail(const QString& fieldPath, const QString& problem)
{
    if (m_error.isEmpty()) {
        m_error = fieldPath.isEmpty()
            ? QStringLiteral("%1: %2").arg(m_fileName, problem)
            : QStringLiteral("%1: field '%2': %3").arg(m_fileName, fieldPath, problem);
    }
    return false;
}

} // namespace vct::doc
