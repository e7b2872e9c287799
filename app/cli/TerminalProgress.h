#pragma once

#include <string>

namespace vct::cli {

/**
 * Reports a long job's progress on stderr: a terminal gets one line redrawn in place at every percent, a log
 * file a line per 10%, so CI logs stay short.
 */
class TerminalProgress {
public:
    explicit TerminalProgress(std::string label);

    void operator()(double fraction);
    /** Ends the redrawn line on a terminal. */
    void finish() const;

private:
    std::string m_label;
    bool m_terminal;
    int m_lastPercent = -1;
};

} // namespace vct::cli
