#include "ModelPreflight.h"

#include <QFile>
#include <QFileInfo>

#include <array>
#include <utility>

namespace vct::doc {

namespace {

/** Bytes of one PLY scalar, or 0 for a name that is not a PLY type. */
int plyTypeSize(const QByteArray& type)
{
    static const std::array<std::pair<const char*, int>, 16> types { { { "char", 1 }, { "uchar", 1 },
        { "int8", 1 }, { "uint8", 1 }, { "short", 2 }, { "ushort", 2 }, { "int16", 2 }, { "uint16", 2 },
        { "int", 4 }, { "uint", 4 }, { "int32", 4 }, { "uint32", 4 }, { "float", 4 }, { "float32", 4 },
        { "double", 8 }, { "float64", 8 } } };
    for (const auto& [name, size] : types)
        if (type == name)
            return size;
    return 0;
}

bool isIntegerPlyType(const QByteArray& type)
{
    return plyTypeSize(type) > 0 && !type.startsWith("float") && type != "double";
}

} // namespace

QString ModelPreflight::check(const QString& path)
{
    QFile file(path);
    const qint64 size = file.size();
    if (size > kMaxModelBytes)
        return QStringLiteral("the file is %1 MiB; models over %2 MiB are refused")
            .arg(size >> 20)
            .arg(kMaxModelBytes >> 20);
    if (!file.open(QIODevice::ReadOnly))
        return QStringLiteral("cannot read the file: %1").arg(file.errorString());
    const QByteArray head = file.peek(4);
    const QString suffix = QFileInfo(path).suffix().toLower();

    // Assimp picks the PLY reader by extension or by the magic word: check whichever would reach it.
    if (suffix == QLatin1String("ply") || head.startsWith("ply")) {
        const QByteArray header = file.read(kMaxPlyHeaderBytes + 1);
        return checkPly(header, size);
    }
    if (suffix == QLatin1String("gltf") || (suffix != QLatin1String("glb") && head.startsWith("{")))
        return checkJsonNesting(file.readAll());
    if (suffix == QLatin1String("glb") || head == "glTF") {
        // GLB: 12-byte header, then chunk 0 (length, type "JSON", data).
        const QByteArray start = file.read(20);
        if (start.size() < 20 || start.mid(16, 4) != "JSON")
            return QStringLiteral("a GLB file must start with a JSON chunk");
        const quint32 length = quint32(quint8(start[12])) | quint32(quint8(start[13])) << 8
            | quint32(quint8(start[14])) << 16 | quint32(quint8(start[15])) << 24;
        if (qint64(length) > size - 20)
            return QStringLiteral("the GLB JSON chunk claims %1 bytes, more than the file holds").arg(length);
        return checkJsonNesting(file.read(qint64(length)));
    }
    return {};
}

QString ModelPreflight::checkPly(const QByteArray& bytes, qint64 fileSize)
{
    const qsizetype end = bytes.indexOf("end_header");
    if (end < 0)
        return bytes.size() > kMaxPlyHeaderBytes
            ? QStringLiteral("PLY header longer than %1 bytes").arg(kMaxPlyHeaderBytes)
            : QStringLiteral("PLY header has no end_header line (truncated?)");
    for (qsizetype i = 0; i < end; ++i) {
        const char c = bytes[i];
        if (!(c == '\n' || c == '\r' || c == '\t' || (c >= ' ' && c <= '~')))
            return QStringLiteral("PLY header byte %1 is not printable ASCII").arg(i);
    }
    const QList<QByteArray> lines = bytes.left(end).split('\n');
    if (lines.isEmpty() || lines.front().trimmed() != "ply")
        return QStringLiteral("a PLY file must start with the line 'ply'");

    struct Element {
        QByteArray name;
        qint64 count = 0;
        qint64 minBinaryBytes = 0; ///< one instance, with every list empty
        int properties = 0;
    };
    QList<Element> elements;
    QByteArray format;
    for (qsizetype n = 1; n < lines.size(); ++n) {
        const QList<QByteArray> words = lines[n].simplified().split(' ');
        const QByteArray& keyword = words.front();
        const QString where = QStringLiteral("PLY header line %1: ").arg(n + 1);
        if (keyword.isEmpty() || keyword == "comment" || keyword == "obj_info")
            continue;
        if (keyword == "format") {
            if (!format.isEmpty() || !elements.isEmpty())
                return where + QStringLiteral("'format' must come once, before the elements");
            if (words.size() != 3
                || (words[1] != "ascii" && words[1] != "binary_little_endian"
                    && words[1] != "binary_big_endian")
                || words[2] != "1.0")
                return where
                    + QStringLiteral("unknown format '%1'").arg(QString::fromLatin1(lines[n].trimmed()));
            format = words[1];
        } else if (keyword == "element") {
            if (format.isEmpty())
                return where + QStringLiteral("an element before the 'format' line");
            bool ok = false;
            const qint64 count = words.size() == 3 ? words[2].toLongLong(&ok) : -1;
            if (!ok || count < 0 || count > 0x7fffffff)
                return where + QStringLiteral("an element needs a name and a count from 0 to 2^31-1");
            elements.push_back({ words[1], count, 0, 0 });
        } else if (keyword == "property") {
            if (elements.isEmpty())
                return where + QStringLiteral("a property before any element");
            Element& element = elements.back();
            if (words.size() == 3 && plyTypeSize(words[1]) > 0) {
                element.minBinaryBytes += plyTypeSize(words[1]);
            } else if (words.size() == 5 && words[1] == "list" && isIntegerPlyType(words[2])
                && plyTypeSize(words[3]) > 0) {
                element.minBinaryBytes += plyTypeSize(words[2]);
            } else {
                return where
                    + QStringLiteral("not a valid property: '%1'")
                          .arg(QString::fromLatin1(lines[n].trimmed()));
            }
            ++element.properties;
        } else {
            return where + QStringLiteral("unknown keyword '%1'").arg(QString::fromLatin1(keyword.left(32)));
        }
    }
    if (format.isEmpty())
        return QStringLiteral("PLY header has no 'format' line");
    if (elements.isEmpty())
        return QStringLiteral("PLY header declares no elements");

    // Counts must fit in the bytes that follow the header: a binary instance takes at least its fixed-size
    // fields, an ASCII one at least one character per property. This refuses "2^31 vertices" in a 1 KB file
    // before Assimp allocates for them.
    const qint64 body = fileSize - qint64(bytes.indexOf('\n', end) + 1);
    qint64 needed = 0;
    for (const Element& element : elements) {
        if (element.count > 0 && element.properties == 0)
            return QStringLiteral("PLY element '%1' has %2 instances but no properties")
                .arg(QString::fromLatin1(element.name.left(32)))
                .arg(element.count);
        needed += element.count * (format == "ascii" ? element.properties : element.minBinaryBytes);
        if (needed > body)
            return QStringLiteral(
                "PLY element '%1' claims %2 instances, more than the %3 bytes of data can hold")
                .arg(QString::fromLatin1(element.name.left(32)))
                .arg(element.count)
                .arg(qMax<qint64>(body, 0));
    }
    return {};
}

QString ModelPreflight::checkJsonNesting(const QByteArray& json)
{
    int depth = 0;
    bool inString = false;
    for (qsizetype i = 0; i < json.size(); ++i) {
        const char c = json[i];
        if (inString) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                inString = false;
            continue;
        }
        if (c == '"') {
            inString = true;
        } else if (c == '{' || c == '[') {
            if (++depth > kMaxJsonDepth)
                return QStringLiteral("JSON nests deeper than %1 levels at byte %2")
                    .arg(kMaxJsonDepth)
                    .arg(i);
        } else if (c == '}' || c == ']') {
            if (--depth < 0)
                return QStringLiteral("JSON closes a bracket it never opened at byte %1").arg(i);
        }
    }
    return {};
}

} // namespace vct::doc
