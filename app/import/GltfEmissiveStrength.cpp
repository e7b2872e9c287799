#include "GltfEmissiveStrength.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtEndian>

#include <cmath>

namespace vct::doc {

namespace {

constexpr quint32 kGlbMagic = 0x46546C67; // "glTF"
constexpr quint32 kGlbJsonChunk = 0x4E4F534A; // "JSON"
constexpr int kGlbHeaderBytes = 12;
constexpr int kGlbChunkHeaderBytes = 8;

bool extractJson(const QByteArray& bytes, QByteArray* json)
{
    if (bytes.size() < kGlbHeaderBytes || qFromLittleEndian<quint32>(bytes.constData()) != kGlbMagic) {
        *json = bytes;
        return true;
    }
    if (bytes.size() < kGlbHeaderBytes + kGlbChunkHeaderBytes)
        return false;
    const quint32 length = qFromLittleEndian<quint32>(bytes.constData() + kGlbHeaderBytes);
    const quint32 type = qFromLittleEndian<quint32>(bytes.constData() + kGlbHeaderBytes + 4);
    const qsizetype start = kGlbHeaderBytes + kGlbChunkHeaderBytes;
    if (type != kGlbJsonChunk || qsizetype(length) > bytes.size() - start)
        return false;
    *json = bytes.mid(start, qsizetype(length));
    return true;
}

} // namespace

bool GltfEmissiveStrength::read(const QString& path, std::vector<Entry>& entries, QString* error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        if (error)
            *error = QStringLiteral("%1: cannot open: %2").arg(path, file.errorString());
        return false;
    }
    QByteArray json;
    if (!extractJson(file.readAll(), &json)) {
        if (error)
            *error = QStringLiteral("%1: malformed GLB header or JSON chunk").arg(path);
        return false;
    }
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (!document.isObject()) {
        if (error)
            *error = QStringLiteral("%1: invalid glTF JSON: %2").arg(path, parseError.errorString());
        return false;
    }

    entries.clear();
    const QJsonArray materials = document.object().value(QStringLiteral("materials")).toArray();
    for (const QJsonValue& value : materials) {
        const QJsonObject material = value.toObject();
        Entry entry;
        entry.name = material.value(QStringLiteral("name")).toString();
        const QJsonValue strength = material.value(QStringLiteral("extensions"))
                                        .toObject()
                                        .value(QStringLiteral("KHR_materials_emissive_strength"))
                                        .toObject()
                                        .value(QStringLiteral("emissiveStrength"));
        if (strength.isDouble() && std::isfinite(strength.toDouble()) && strength.toDouble() >= 0.0)
            entry.strength = float(strength.toDouble());
        entries.push_back(entry);
    }
    return true;
}

float GltfEmissiveStrength::strengthFor(
    const std::vector<Entry>& entries, const QString& name, unsigned index)
{
    if (index < entries.size() && entries[index].name == name)
        return entries[index].strength;
    const Entry* match = nullptr;
    int matches = 0;
    for (const Entry& entry : entries) {
        if (!name.isEmpty() && entry.name == name) {
            match = &entry;
            ++matches;
        }
    }
    if (matches == 1)
        return match->strength;
    if (index < entries.size())
        return entries[index].strength;
    return 1.0f;
}

} // namespace vct::doc
