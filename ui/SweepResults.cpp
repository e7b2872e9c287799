#include "SweepResults.h"

#include <QFile>

#include <algorithm>
#include <cmath>

namespace vct::ui {

bool SweepResults::load(const QString& path, QString* error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        if (error)
            *error = QStringLiteral("cannot open '%1': %2").arg(path, file.errorString());
        return false;
    }
    QString parseError;
    if (!parse(QString::fromUtf8(file.readAll()), &parseError)) {
        if (error)
            *error = QStringLiteral("%1: %2").arg(path, parseError);
        return false;
    }
    return true;
}

bool SweepResults::parse(const QString& text, QString* error)
{
    m_points.clear();
    m_skipped = 0;
    const QStringList lines = text.split(QLatin1Char('\n'));
    int lineIndex = 0;
    while (lineIndex < lines.size() && lines[lineIndex].trimmed().isEmpty())
        ++lineIndex;
    if (lineIndex == lines.size()) {
        if (error)
            *error = QStringLiteral("the file is empty");
        return false;
    }
    QStringList header = splitLine(lines[lineIndex++]);
    for (QString& name : header)
        name = name.trimmed().toLower();
    const auto column = [&](std::initializer_list<const char*> names) {
        for (const char* name : names)
            if (const qsizetype index = header.indexOf(QLatin1String(name)); index >= 0)
                return int(index);
        return -1;
    };
    const int labelColumn = column({ "label" });
    const int gpuColumn = column({ "gpu_ms" });
    const int wallColumn = column({ "wall_ms", "time_ms" });
    const int secondsColumn = column({ "seconds" });
    const int errorColumn = column({ "rel_mse" });
    const int kindColumn = column({ "kind" });
    if (errorColumn < 0 || (gpuColumn < 0 && wallColumn < 0 && secondsColumn < 0)) {
        if (error)
            *error = QStringLiteral("needs a rel_mse column and a gpu_ms (or wall_ms, or seconds) column");
        return false;
    }

    for (; lineIndex < lines.size(); ++lineIndex) {
        if (lines[lineIndex].trimmed().isEmpty())
            continue;
        const QStringList fields = splitLine(lines[lineIndex]);
        const auto field = [&](int index) {
            return index >= 0 && index < fields.size() ? fields[index].trimmed() : QString();
        };
        Point point;
        point.label = labelColumn >= 0 ? field(labelColumn) : QStringLiteral("row %1").arg(lineIndex);
        point.reference = field(kindColumn).compare(QLatin1String("reference"), Qt::CaseInsensitive) == 0;
        bool timeOk = false, errorOk = false;
        // As vct-bench plots it: GPU ms for the cone tracer, wall-clock ms for the path tracer (which has no
        // GPU time); whichever the row has when its own is empty (the writer leaves unknown values empty).
        const int first = point.reference ? wallColumn : gpuColumn;
        const int second = point.reference ? gpuColumn : wallColumn;
        if (!field(first).isEmpty())
            point.timeMs = field(first).toDouble(&timeOk);
        else if (!field(second).isEmpty())
            point.timeMs = field(second).toDouble(&timeOk);
        else if (!field(secondsColumn).isEmpty())
            point.timeMs = field(secondsColumn).toDouble(&timeOk) * 1000.0;
        point.relativeMse = field(errorColumn).toDouble(&errorOk);
        const bool plottable = timeOk && errorOk && std::isfinite(point.timeMs)
            && std::isfinite(point.relativeMse) && point.timeMs > 0.0 && point.relativeMse > 0.0;
        if (plottable)
            m_points.push_back(point);
        else
            ++m_skipped;
    }
    return true;
}

int SweepResults::count(bool reference) const
{
    return int(std::count_if(m_points.begin(), m_points.end(),
        [reference](const Point& point) { return point.reference == reference; }));
}

QStringList SweepResults::splitLine(const QString& line)
{
    QStringList fields;
    QString current;
    bool quoted = false;
    for (qsizetype i = 0; i < line.size(); ++i) {
        const QChar c = line[i];
        if (quoted) {
            if (c == QLatin1Char('"') && i + 1 < line.size() && line[i + 1] == QLatin1Char('"')) {
                current += c;
                ++i;
            } else if (c == QLatin1Char('"')) {
                quoted = false;
            } else {
                current += c;
            }
        } else if (c == QLatin1Char('"')) {
            quoted = true;
        } else if (c == QLatin1Char(',')) {
            fields << current;
            current.clear();
        } else if (c != QLatin1Char('\r')) {
            current += c;
        }
    }
    fields << current;
    return fields;
}

} // namespace vct::ui
