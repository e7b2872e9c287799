#pragma once

#include "scene/Camera.h"

#include <cstddef>
#include <deque>

namespace vct::ui {

/**
 * The cameras the view was at before its last completed gestures (orbit, pan, zoom, fly, frame, reset), for
 * View > Undo view. Camera moves stay off the document's undo stack (they are no edits), yet a view lost in
 * a big scene needs a way back; the oldest entries give way beyond kCapacity.
 */
class CameraHistory {
public:
    static constexpr std::size_t kCapacity = 32;

    /** Keeps @p before unless the gesture left the camera where it was (a click, a zoom against the limit).
     */
    void record(const render::Camera& before, const render::Camera& after);
    bool isEmpty() const { return m_cameras.empty(); }
    std::size_t size() const { return m_cameras.size(); }
    /** Removes and returns the newest camera; the history must not be empty. */
    render::Camera takeLast();
    void clear() { m_cameras.clear(); }

private:
    std::deque<render::Camera> m_cameras;
};

} // namespace vct::ui
