#pragma once

// Complete type: QPointer<Document> members are destroyed in code moc generates.
#include "document/Document.h"

#include <glm/vec3.hpp>

#include <QDockWidget>
#include <QPointer>

#include <map>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace vct::render {
struct Material;
}

namespace vct::ui {

class ColorButton;

/**
 * Edits one material: the selected node's, or any other picked in the combo. Colours are linear RGB in
 * [0, 1]. Emission is edited as an Emissive switch times colour times strength (W/(m²·sr)); switching it
 * off stores zero emission in the document but keeps the colour and strength here, per material, so
 * switching it back on restores them. Every change is one Document::setMaterial call naming its field: a run
 * of changes to one field in one gesture (until Enter, the box losing focus or the colour dialog closing) is
 * one undo step, a change of another field the next.
 */
class MaterialDock : public QDockWidget {
    Q_OBJECT

public:
    explicit MaterialDock(QWidget* parent = nullptr);

    /** The dock does not own the document; null disables the editors. */
    void setDocument(doc::Document* document);

    /** Index of the material being edited, or -1. */
    int currentMaterial() const { return m_material; }
    /** Edits material `index` (independent of the node selection until the selection changes). */
    void setCurrentMaterial(int index);

private:
    void onDocumentChanged(const doc::ChangeEvent& event);
    void onSelectionChanged(int node);
    void rebuildCombo();
    /** Shows the document's values of the current material without emitting edits. */
    void loadMaterial();
    void updateUsage();
    void updateWarning();
    /** Reads the editors into a copy of the current material and hands it to the document. */
    void apply();
    glm::vec3 uiEmission() const;

    QPointer<doc::Document> m_document;
    QMetaObject::Connection m_changedConnection;
    QMetaObject::Connection m_selectionConnection;
    int m_material = -1;
    int m_shownMaterial = -1; ///< The material the editors show, to tell a reload from a switch.
    bool m_applying = false; ///< True while our own setMaterial runs: the editors already show the result.

    /** Emission colour and strength remembered while a material's Emissive switch is off, by material index.
     */
    struct EmissionMemory {
        glm::vec3 color { 1.0f };
        double strength = 1.0;
    };
    std::map<int, EmissionMemory> m_emissionMemory;

    QComboBox* m_combo = nullptr;
    QLabel* m_usage = nullptr;
    ColorButton* m_albedo = nullptr;
    QLabel* m_texture = nullptr;
    QCheckBox* m_emissive = nullptr;
    QCheckBox* m_doubleSided = nullptr;
    ColorButton* m_emissionColor = nullptr;
    QDoubleSpinBox* m_strength = nullptr;
    ColorButton* m_specular = nullptr;
    QDoubleSpinBox* m_shininess = nullptr;
    QLabel* m_warning = nullptr;
};

} // namespace vct::ui
