#include "UndoShortcutFilter.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QDockWidget>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPointer>

namespace vct::ui {

UndoShortcutFilter::UndoShortcutFilter(QWidget* window, QAction* undo, QAction* redo)
    : QObject(window)
    , m_window(window)
    , m_undo(undo)
    , m_redo(redo)
{
}

bool UndoShortcutFilter::eventFilter(QObject* watched, QEvent* event)
{
    if (event->type() != QEvent::ShortcutOverride && event->type() != QEvent::KeyPress)
        return false;
    const QKeySequence pressed(static_cast<QKeyEvent*>(event)->keyCombination());
    QAction* action = m_undo->shortcuts().contains(pressed) ? m_undo
        : m_redo->shortcuts().contains(pressed)             ? m_redo
                                                            : nullptr;
    if (!action)
        return false;
    QWidget* editor = editorIn(watched);
    if (!editor)
        return false;
    if (event->type() == QEvent::ShortcutOverride) {
        // Claimed, so that the key comes as a key press to trigger the action below: the shortcut itself
        // may not fire (a floating panel is another window), and must not fire a second time.
        event->accept();
        return true;
    }
    // Focus leaving commits the field exactly as clicking elsewhere would (a spin box interprets its text, a
    // name is applied, an item editor writes its data); the focus then returns, so typing can go on.
    QPointer<QWidget> focused = editor;
    editor->clearFocus();
    action->trigger();
    if (focused && focused->isVisible() && focused->isEnabled())
        focused->setFocus(Qt::OtherFocusReason);
    return true;
}

QWidget* UndoShortcutFilter::editorIn(QObject* watched) const
{
    auto* widget = qobject_cast<QWidget*>(watched);
    if (!widget)
        return nullptr;
    QWidget* editor = nullptr;
    if (auto* spin = qobject_cast<QAbstractSpinBox*>(widget))
        editor = spin;
    else if (auto* line = qobject_cast<QLineEdit*>(widget))
        editor = qobject_cast<QAbstractSpinBox*>(line->parentWidget()) ? line->parentWidget() : line;
    if (!editor)
        return nullptr;
    // The window's fields, docked or floating; a dialog's (a colour dialog's hex field) keep their own undo.
    for (QWidget* w = editor; w; w = w->parentWidget()) {
        if (w == m_window)
            return editor;
        if (w->isWindow() && !qobject_cast<QDockWidget*>(w))
            return nullptr;
    }
    return nullptr;
}

} // namespace vct::ui
