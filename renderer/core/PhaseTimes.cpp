#include "core/PhaseTimes.h"

#include <algorithm>
#include <utility>

namespace vct::render {

PhaseTimes::Scope::Scope(Scope&& other) noexcept
    : m_query(std::exchange(other.m_query, nullptr))
{
}

PhaseTimes::Scope::~Scope()
{
    if (m_query)
        m_query->end();
}

void PhaseTimes::start(bool enabled)
{
    m_enabled = enabled;
    m_phases.clear();
    m_runPhases.clear();
}

PhaseTimes::Scope PhaseTimes::time(const char* phase)
{
    if (!m_enabled)
        return Scope(nullptr);
    const auto named = std::find(m_phases.begin(), m_phases.end(), phase);
    const std::size_t index = std::size_t(named - m_phases.begin());
    if (named == m_phases.end())
        m_phases.emplace_back(phase);
    if (m_runPhases.size() == m_queries.size())
        m_queries.push_back(gl::TimerQuery::create());
    gl::TimerQuery& query = m_queries[m_runPhases.size()];
    m_runPhases.push_back(index);
    query.begin();
    return Scope(&query);
}

std::vector<PassStats> PhaseTimes::read(const std::string& prefix) const
{
    std::vector<double> ms(m_phases.size(), 0.0);
    std::vector<int> runs(m_phases.size(), 0);
    for (std::size_t run = 0; run < m_runPhases.size(); ++run) {
        ms[m_runPhases[run]] += m_queries[run].elapsedMs();
        ++runs[m_runPhases[run]];
    }
    std::vector<PassStats> stats;
    for (std::size_t i = 0; i < m_phases.size(); ++i)
        stats.push_back({ prefix + ": " + m_phases[i], "run",
            std::to_string(runs[i]) + (runs[i] == 1 ? " run" : " runs"), ms[i] });
    return stats;
}

} // namespace vct::render
