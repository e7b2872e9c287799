#include "CameraHistory.h"

#include "document/DocumentState.h"

namespace vct::ui {

void CameraHistory::record(const render::Camera& before, const render::Camera& after)
{
    if (doc::sameCamera(before, after))
        return;
    m_cameras.push_back(before);
    while (m_cameras.size() > kCapacity)
        m_cameras.pop_front();
}

render::Camera CameraHistory::takeLast()
{
    const render::Camera camera = m_cameras.back();
    m_cameras.pop_back();
    return camera;
}

} // namespace vct::ui
