#pragma once

#include <glm/vec3.hpp>

#include <QToolButton>

namespace vct::ui {

/**
 * A swatch that edits one linear-RGB colour (each channel in [0, 1]) and prints its linear values.
 * Clicking opens a QColorDialog that previews live; Cancel restores the colour the dialog opened with.
 */
class ColorButton : public QToolButton {
    Q_OBJECT

public:
    explicit ColorButton(QWidget* parent = nullptr);

    /** Linear RGB. */
    glm::vec3 color() const { return m_color; }
    /** Shows `linear` without emitting colorChanged (for loading from the document). */
    void setColor(const glm::vec3& linear);

    /** Title of the colour dialog, e.g. "Albedo". */
    void setDialogTitle(const QString& title) { m_dialogTitle = title; }

signals:
    /** The user picked a colour (linear RGB); emitted for every live preview step of the dialog too. */
    void colorChanged(const glm::vec3& linear);
    /** The dialog closed, picked or cancelled: its live preview steps were one gesture. */
    void editingFinished();

private:
    void openDialog();
    void pick(const glm::vec3& linear);
    void refresh();

    glm::vec3 m_color { 0.0f };
    QString m_dialogTitle;
};

} // namespace vct::ui
