#pragma once

#include <QDialog>

class QTableWidget;

namespace vct::ui {

/**
 * Help > Keyboard shortcuts: every shortcut of the window's actions (menus and panels), gathered when the
 * dialog opens so it cannot drift from the real ones, then the viewport's own keys and mouse gestures
 * (ViewportWidget::inputBindings). Non-modal, so it can stay open beside the editor.
 */
class ShortcutsDialog : public QDialog {
    Q_OBJECT

public:
    /** Lists the shortcuts of `window`'s actions (and the viewport's keys). */
    explicit ShortcutsDialog(QWidget* window, QWidget* parent = nullptr);

    QTableWidget* table() const { return m_table; }

    /** Shows `window`'s shortcuts dialog, made on first use and raised when already open. */
    static ShortcutsDialog* showFor(QWidget* window);

private:
    QTableWidget* m_table = nullptr;
};

} // namespace vct::ui
