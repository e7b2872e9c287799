#pragma once

#include <QDialog>

namespace vct::ui {

/**
 * Help > About VCT Studio: the version, the libraries the editor uses and their licences, where the bundled
 * scenes come from and under what terms, and where the documentation is. Non-modal, so it never blocks the
 * editor (nor a test run with VCT_NO_DIALOGS).
 */
class AboutDialog : public QDialog {
    Q_OBJECT

public:
    explicit AboutDialog(QWidget* parent = nullptr);

    /** The version of CMake's project(). */
    static QString version();
    /** The dialog's text, rich text. */
    static QString text();
    /** Shows `parent`'s About dialog, made on first use and raised when already open. */
    static AboutDialog* showFor(QWidget* parent);
};

} // namespace vct::ui
