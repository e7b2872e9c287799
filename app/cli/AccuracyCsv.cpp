#include "cli/AccuracyCsv.h"
#include "cli/ReportText.h"
#include "files/CsvRecords.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>

namespace vct::cli {

namespace {

std::string number(double v)
{
    if (!std::isfinite(v))
        return std::isnan(v) ? std::string() : std::string(v > 0 ? "inf" : "-inf");
    char text[64];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

bool readNumber(const std::string& text, double& out)
{
    if (text.empty()) {
        out = AccuracyRow::kNone;
        return true;
    }
    char* end = nullptr;
    out = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size();
}

bool readInt(const std::string& text, int& out)
{
    double v = 0.0;
    if (!readNumber(text, v))
        return false;
    out = std::isfinite(v) ? int(v) : 0;
    return true;
}

struct Column {
    std::string name;
    std::function<std::string(const AccuracyRow&)> print;
    std::function<bool(AccuracyRow&, const std::string&)> parse;
    bool required;
};

const std::vector<Column>& table()
{
    auto text = [](std::string AccuracyRow::*member, const char* name, bool required) {
        return Column { name, [member](const AccuracyRow& r) { return r.*member; },
            [member](AccuracyRow& r, const std::string& v) {
                r.*member = v;
                return true;
            },
            required };
    };
    auto real = [](double AccuracyRow::*member, const char* name) {
        return Column { name, [member](const AccuracyRow& r) { return number(r.*member); },
            [member](AccuracyRow& r, const std::string& v) { return readNumber(v, r.*member); }, false };
    };
    auto integer = [](int AccuracyRow::*member, const char* name, bool required) {
        return Column { name, [member](const AccuracyRow& r) { return std::to_string(r.*member); },
            [member](AccuracyRow& r, const std::string& v) { return readInt(v, r.*member); }, required };
    };
    static const std::vector<Column> columns = {
        text(&AccuracyRow::kind, "kind", true),
        text(&AccuracyRow::label, "label", true),
        text(&AccuracyRow::setting, "setting", false),
        text(&AccuracyRow::value, "value", false),
        real(&AccuracyRow::gpuMs, "gpu_ms"),
        real(&AccuracyRow::coneMs, "cone_ms"),
        real(&AccuracyRow::cameraMs, "camera_ms"),
        real(&AccuracyRow::relMse, "rel_mse"),
        real(&AccuracyRow::rmse, "rmse"),
        real(&AccuracyRow::psnr, "psnr"),
        real(&AccuracyRow::ssim, "ssim"),
        real(&AccuracyRow::meanRatio, "mean_ratio"),
        integer(&AccuracyRow::spp, "spp", false),
        real(&AccuracyRow::wallMs, "wall_ms"),
        real(&AccuracyRow::cpuMs, "cpu_ms"),
        integer(&AccuracyRow::point, "point", true),
        integer(&AccuracyRow::width, "width", false),
        integer(&AccuracyRow::height, "height", false),
        integer(&AccuracyRow::jobs, "jobs", false),
        text(&AccuracyRow::machine, "machine", false),
        real(&AccuracyRow::loadAverage, "load_average"),
    };
    return columns;
}

} // namespace

const std::vector<std::string>& AccuracyCsv::columns()
{
    static const std::vector<std::string> names = [] {
        std::vector<std::string> out;
        for (const Column& c : table())
            out.push_back(c.name);
        return out;
    }();
    return names;
}

std::string AccuracyCsv::write(const std::vector<AccuracyRow>& rows)
{
    std::string out;
    for (std::size_t c = 0; c < table().size(); ++c) {
        if (c)
            out += ',';
        out += table()[c].name;
    }
    out += '\n';
    for (const AccuracyRow& row : rows) {
        for (std::size_t c = 0; c < table().size(); ++c) {
            if (c)
                out += ',';
            out += report_text::csvField(table()[c].print(row));
        }
        out += '\n';
    }
    return out;
}

bool AccuracyCsv::read(const std::string& text, const std::string& sourceName, std::vector<AccuracyRow>& rows,
    std::string* error)
{
    const auto fail = [&](const std::string& message) {
        if (error)
            *error = sourceName + ": " + message;
        return false;
    };
    const std::vector<std::vector<std::string>> lines = files::CsvRecords::parse(text);
    if (lines.empty())
        return fail("empty file, expected a header line");
    std::map<std::string, std::size_t> position;
    for (std::size_t i = 0; i < lines[0].size(); ++i)
        position[lines[0][i]] = i;
    for (const Column& c : table())
        if (c.required && !position.count(c.name))
            return fail("the header has no '" + c.name + "' column");
    std::vector<AccuracyRow> read;
    for (std::size_t l = 1; l < lines.size(); ++l) {
        AccuracyRow row;
        for (const Column& c : table()) {
            const auto at = position.find(c.name);
            if (at == position.end())
                continue;
            const std::string field = at->second < lines[l].size() ? lines[l][at->second] : std::string();
            if (!c.parse(row, field))
                return fail(
                    "record " + std::to_string(l) + ", column '" + c.name + "': cannot read '" + field + "'");
        }
        if (row.kind != "vct" && row.kind != "reference")
            return fail("record " + std::to_string(l) + ": kind must be 'vct' or 'reference', not '"
                + row.kind + "'");
        read.push_back(row);
    }
    rows.insert(rows.end(), read.begin(), read.end());
    return true;
}

} // namespace vct::cli
