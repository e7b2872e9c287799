#include "gl/TimerQuery.h"

namespace vct::gl {

void deleteQuery(GLuint id)
{
    glDeleteQueries(1, &id);
}

TimerQuery TimerQuery::create()
{
    TimerQuery q;
    GLuint ids[2] = { 0, 0 };
    glCreateQueries(GL_TIMESTAMP, 2, ids);
    q.m_start = Handle<deleteQuery>(ids[0]);
    q.m_end = Handle<deleteQuery>(ids[1]);
    return q;
}

void TimerQuery::begin()
{
    glQueryCounter(m_start.id(), GL_TIMESTAMP);
}

void TimerQuery::end()
{
    glQueryCounter(m_end.id(), GL_TIMESTAMP);
    m_issued = true;
}

double TimerQuery::elapsedMs() const
{
    if (!m_issued)
        return 0.0;
    GLuint64 start = 0, end = 0;
    glGetQueryObjectui64v(m_start.id(), GL_QUERY_RESULT, &start);
    glGetQueryObjectui64v(m_end.id(), GL_QUERY_RESULT, &end);
    return end > start ? double(end - start) * 1e-6 : 0.0;
}

} // namespace vct::gl
