#pragma once

#include "core/FrameStats.h"
#include "document/Document.h"
#include "ui/MainWindow.h"
#include "ui/ViewportWidget.h"

#include <QSignalSpy>
#include <QSize>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTest>
#include <QUndoStack>
#include <QtGlobal>

#include <memory>
#include <optional>

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

/**
 * The editor's window on `scene` with a 32³ grid (small and quick on llvmpipe) and no undo history yet, shown
 * at `size` (the editor's own first size by default: at 960 wide the docks left the viewport a 250-pixel
 * strip) and exposed; null when it never appears.
 */
inline std::unique_ptr<ui::MainWindow> showEditor(const QString& scene, QSize size = QSize(1280, 800))
{
    auto window = std::make_unique<ui::MainWindow>();
    window->openInitial(scene);
    render::RenderSettings settings = window->document()->state().settings;
    settings.voxelResolution = 32;
    window->document()->setSettings(settings);
    window->document()->undoStack()->clear();
    window->resize(size);
    window->show();
    if (!QTest::qWaitForWindowExposed(window.get()))
        return nullptr;
    return window;
}

/** The stats of the very next frame the viewport renders, complete or not, or empty stats after 20 s. */
inline render::FrameStats firstFrame(ui::MainWindow& window)
{
    QSignalSpy spy(window.viewport(), &ui::ViewportWidget::frameRendered);
    window.viewport()->update();
    if (!spy.wait(20000))
        return {};
    return spy.first().first().value<render::FrameStats>();
}

/**
 * The stats of the next complete frame the viewport of @p window renders, or empty stats (width 0) if none
 * comes in 20 s. A staged rebuild's deferred frames are passed over: the viewport renders them by itself.
 */
inline render::FrameStats nextFrame(ui::MainWindow& window)
{
    std::optional<render::FrameStats> complete;
    const QMetaObject::Connection watching = QObject::connect(window.viewport(),
        &ui::ViewportWidget::frameRendered, window.viewport(), [&complete](const render::FrameStats& stats) {
            if (!complete && !stats.deferred)
                complete = stats;
        });
    window.viewport()->update();
    if (!QTest::qWaitFor([&complete] { return complete.has_value(); }, 20000))
        complete.reset();
    QObject::disconnect(watching);
    return complete.value_or(render::FrameStats {});
}

/** The first node whose name starts with @p prefix, or -1. */
inline int nodeNamed(const doc::Document& document, const QString& prefix)
{
    const auto& nodes = document.state().nodes;
    for (std::size_t i = 0; i < nodes.size(); ++i)
        if (nodes[i].name.startsWith(prefix))
            return int(i);
    return -1;
}

} // namespace vct::test
