#pragma once

#include <QObject>

class QAction;
class QWidget;

namespace vct::ui {

/**
 * Makes the window's Undo and Redo keys undo the document while a spin box or line edit of the window (or of
 * one of its floating panels) has focus. Such a field would otherwise take Ctrl+Z for its own text: the
 * shortcut never reached Edit > Undo, and undoing the typing re-typed the value, which was yet another edit.
 * The field's pending text is committed first, as leaving the field would, and the field keeps its focus.
 * Install on the application; the keys are the actions' shortcuts.
 */
class UndoShortcutFilter : public QObject {
    Q_OBJECT

public:
    UndoShortcutFilter(QWidget* window, QAction* undo, QAction* redo);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    /** The spin box or line edit `watched` is or belongs to, if it is in the window; else null. */
    QWidget* editorIn(QObject* watched) const;

    QWidget* m_window;
    QAction* m_undo;
    QAction* m_redo;
};

} // namespace vct::ui
