#pragma once

#include "gl/Handle.h"

namespace vct::gl {

void deleteQuery(GLuint id);

/**
 * GPU time of one pass from two GL_TIMESTAMP queries. Timestamps rather than GL_TIME_ELAPSED: llvmpipe
 * reports elapsed time wrongly for compute dispatches and for the first draw after a flush, but orders
 * timestamps correctly. Results are read after the frame, never inside it.
 */
class TimerQuery {
public:
    static TimerQuery create();
    void begin();
    void end();
    /** Blocks until the GPU has the result; milliseconds. */
    double elapsedMs() const;

private:
    Handle<deleteQuery> m_start;
    Handle<deleteQuery> m_end;
    bool m_issued = false;
};

} // namespace vct::gl
