#pragma once

#include "ReferenceRequest.h"
#include "ReferenceUpdate.h"

#include <QObject>
#include <QString>

#include <atomic>
#include <memory>
#include <thread>
#include <vector>

namespace vct::ui {

/**
 * Runs the CPU path tracer (render::ReferenceRenderer) for one ReferenceRequest on a worker thread, pass
 * after pass, and reports each pass through queued signals; the GUI thread never waits for it.
 *
 * Every run gets a job id that all its signals carry. start() and cancel() only ask the running job to stop
 * (std::stop_token) and never join it, because the renderer checks the token between rows but building the
 * scene or scoring a pass cannot be interrupted; a stopped job finishes in the background and its late
 * signals carry an old id, which receivers ignore (compare with currentJobId()). The destructor stops and
 * joins every job, so no worker outlives the object whose signals it emits.
 */
class ReferenceJob : public QObject {
    Q_OBJECT

public:
    explicit ReferenceJob(QObject* parent = nullptr);
    ~ReferenceJob() override;

    /** Stops any running job and starts a new one on @p request; returns the new job's id (> 0). */
    int start(ReferenceRequest request);
    /** Asks the current job to stop; it keeps the passes it finished and then emits finished(id, false). */
    void cancel();
    /** The id of the last job started (0 before the first); signals with another id are stale. */
    int currentJobId() const { return m_jobId; }

signals:
    /** @p doneSpp samples are complete and a pass of @p passSpp more is @p fraction (0..1) done. */
    void progress(int jobId, int doneSpp, int passSpp, double fraction);
    /** A pass finished: the reference so far and its scores. */
    void passFinished(const vct::ui::ReferenceUpdate& update);
    /** The job ended: @p completed when it reached the target, false when it was stopped. */
    void finished(int jobId, bool completed, int samplesPerPixel);
    /** The job could not run (e.g. Embree failed to build the scene). No finished() follows. */
    void failed(int jobId, const QString& message);

private:
    struct Worker {
        std::jthread thread;
        std::shared_ptr<std::atomic<bool>> done;
    };
    void run(int jobId, const ReferenceRequest& request, std::stop_token stop);
    /** Joins workers that have already returned (instant) and drops them. */
    void reapFinished();

    std::vector<Worker> m_workers; ///< The current job last; older ones are stopping.
    int m_jobId = 0;
};

} // namespace vct::ui
