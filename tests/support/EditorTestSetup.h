#pragma once

#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QtGlobal>

namespace vct::test {

/**
 * For a test's initMain(), before the application exists: the viewport's renderer needs GL 4.5 core (Qt must
 * know before it makes a context), a modal dialog would wait forever, and the editor's settings and autosave
 * must not touch the user's.
 */
inline void prepareEditorApplication()
{
    QSurfaceFormat format;
    format.setVersion(4, 5);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    QSurfaceFormat::setDefaultFormat(format);
    qputenv("VCT_NO_DIALOGS", "1");
    QStandardPaths::setTestModeEnabled(true);
}

} // namespace vct::test
