#include "files/CsvRecords.h"

#include <algorithm>
#include <cctype>

namespace vct::files {

namespace {

std::string normalised(std::string_view name)
{
    const auto blank = [](unsigned char c) { return std::isspace(c) != 0; };
    while (!name.empty() && blank(static_cast<unsigned char>(name.front())))
        name.remove_prefix(1);
    while (!name.empty() && blank(static_cast<unsigned char>(name.back())))
        name.remove_suffix(1);
    std::string out(name);
    std::transform(
        out.begin(), out.end(), out.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return out;
}

} // namespace

std::vector<std::vector<std::string>> CsvRecords::parse(std::string_view text)
{
    std::vector<std::vector<std::string>> out;
    std::vector<std::string> record;
    std::string field;
    bool inQuotes = false, fieldStarted = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inQuotes) {
            if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
                field += '"';
                ++i;
            } else if (c == '"') {
                inQuotes = false;
            } else {
                field += c;
            }
        } else if (c == '"') {
            inQuotes = fieldStarted = true;
        } else if (c == ',') {
            record.push_back(field);
            field.clear();
            fieldStarted = true;
        } else if (c == '\n' || c == '\r') {
            if (fieldStarted || !field.empty()) {
                record.push_back(field);
                out.push_back(record);
            }
            record.clear();
            field.clear();
            fieldStarted = false;
        } else {
            field += c;
            fieldStarted = true;
        }
    }
    if (fieldStarted || !field.empty()) {
        record.push_back(field);
        out.push_back(record);
    }
    return out;
}

int CsvRecords::column(const std::vector<std::string>& header, std::initializer_list<std::string_view> names)
{
    for (const std::string_view name : names)
        for (std::size_t i = 0; i < header.size(); ++i)
            if (normalised(header[i]) == normalised(name))
                return int(i);
    return -1;
}

} // namespace vct::files
