#include "SweepResults.h"

#include "files/CsvRecords.h"

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
    const std::vector<std::vector<std::string>> records = files::CsvRecords::parse(text.toStdString());
    if (records.empty()) {
        if (error)
            *error = QStringLiteral("the file is empty");
        return false;
    }
    const std::vector<std::string>& header = records.front();
    const int labelColumn = files::CsvRecords::column(header, { "label" });
    const int gpuColumn = files::CsvRecords::column(header, { "gpu_ms" });
    const int wallColumn = files::CsvRecords::column(header, { "wall_ms", "time_ms" });
    const int secondsColumn = files::CsvRecords::column(header, { "seconds" });
    const int errorColumn = files::CsvRecords::column(header, { "rel_mse" });
    const int kindColumn = files::CsvRecords::column(header, { "kind" });
    if (errorColumn < 0 || (gpuColumn < 0 && wallColumn < 0 && secondsColumn < 0)) {
        if (error)
            *error = QStringLiteral("needs a rel_mse column and a gpu_ms (or wall_ms, or seconds) column");
        return false;
    }

    for (std::size_t row = 1; row < records.size(); ++row) {
        const std::vector<std::string>& fields = records[row];
        const auto field = [&](int index) {
            return index >= 0 && std::size_t(index) < fields.size()
                ? QString::fromStdString(fields[std::size_t(index)]).trimmed()
                : QString();
        };
        Point point;
        point.label = labelColumn >= 0 ? field(labelColumn) : QStringLiteral("row %1").arg(row);
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

} // namespace vct::ui
