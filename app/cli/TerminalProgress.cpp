#include "cli/TerminalProgress.h"

#include <cstdio>
#include <unistd.h>

namespace vct::cli {

TerminalProgress::TerminalProgress(std::string label)
    : m_label(std::move(label))
    , m_terminal(isatty(fileno(stderr)) != 0)
{
}

void TerminalProgress::operator()(double fraction)
{
    const int step = m_terminal ? 1 : 10;
    const int percent = int(fraction * 100.0) / step * step;
    if (percent == m_lastPercent)
        return;
    m_lastPercent = percent;
    std::fprintf(stderr, m_terminal ? "\r%s %3d%%" : "%s %3d%%\n", m_label.c_str(), percent);
    std::fflush(stderr);
}

void TerminalProgress::finish() const
{
    if (m_terminal)
        std::fprintf(stderr, "\n");
}

} // namespace vct::cli
