#pragma once

#include "core/FrameStats.h"
#include "gl/TimerQuery.h"

#include <cstddef>
#include <deque>
#include <string>
#include <vector>

namespace vct::render {

/**
 * GPU time of the phases of one pass's run, summed by phase (the bounce solve's gathers, reinjections and
 * filterings), for --stats and `vct-bench perf`: where a pass's time goes, measured by the build a user runs
 * rather than by a temporary one. Timestamp queries (gl::TimerQuery) inside the pipeline's own pair around
 * the pass. Off unless asked for (Renderer::setPhaseTimes): reading the results waits for the GPU to finish
 * the pass, which an interactive view's frames do not do.
 */
class PhaseTimes {
public:
    /** Ends its phase's timing when it goes out of scope; does nothing when timing is off. */
    class Scope {
    public:
        Scope(Scope&& other) noexcept;
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;
        Scope& operator=(Scope&&) = delete;
        ~Scope();

    private:
        friend class PhaseTimes;
        explicit Scope(gl::TimerQuery* query)
            : m_query(query)
        {
        }
        gl::TimerQuery* m_query;
    };

    /** Forgets the last run's phases; until the next start(), time() records nothing unless `enabled`. */
    void start(bool enabled);
    /** Times what runs until the scope ends, as one more run of `phase` (a name of the caller's). */
    Scope time(const char* phase);
    /**
     * The phases of the last run, in the order each first ran, each the sum of its runs ("N runs" as the
     * reason), named "prefix: phase". Waits for their queries' results.
     */
    std::vector<PassStats> read(const std::string& prefix) const;

private:
    bool m_enabled = false;
    std::vector<std::string> m_phases;
    /// Grows to the most runs one pass has timed, and is reused; a deque, so that a scope's query stays put
    /// while a nested scope adds one.
    std::deque<gl::TimerQuery> m_queries;
    std::vector<std::size_t> m_runPhases; ///< run k's phase (an index into m_phases), timed by m_queries[k]
};

} // namespace vct::render
