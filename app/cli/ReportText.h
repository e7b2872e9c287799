#pragma once

#include <cstdio>
#include <string>

// Text helpers the benchmark reports (Markdown tables, CSV) share, so that both quote and format alike.
namespace vct::cli::report_text {

template <typename... Args> std::string format(const char* pattern, Args... args)
{
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, pattern, args...);
    return buffer;
}

/** A CSV field, quoted (RFC 4180) only when it holds a separator, a quote or a line break. */
std::string csvField(const std::string& text);

} // namespace vct::cli::report_text
