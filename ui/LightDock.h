#pragma once

// Complete type: QPointer<Document> members are destroyed in code moc generates.
#include "document/Document.h"

#include <QDockWidget>
#include <QPointer>

#include <array>
#include <functional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListView;
class QPushButton;
class QWidget;

namespace vct::ui {

class ColorButton;
class SceneTreeModel;

/**
 * The document's lights: a list (the "Lights" group of a SceneTreeModel), Add point / Add directional / Add
 * rect / Add disk / Remove, and editors for the current light. Point lights have a position (metres) and an
 * intensity in W/sr; directional lights a direction (the way the light travels, need not be unit length) and
 * an irradiance in W/m²; rect and disk lights a centre, the direction their front face looks, a size in
 * metres (a disk's diameter), a rect's rotation about its direction, and a radiance in W/(m² sr). Point and
 * spot lights also have a radius in metres and directional lights an angular diameter in degrees, which
 * soften their shadows. Every edit is one Document::setLight / addLight / removeLight; setLight names the
 * field, so a run of edits of one field in one gesture (until Enter or the box losing focus) is one undo step
 * and an edit of another field the next.
 */
class LightDock : public QDockWidget {
    Q_OBJECT

public:
    explicit LightDock(QWidget* parent = nullptr);

    /** The dock does not own the document; null empties the list. */
    void setDocument(doc::Document* document);

    /** Index of the light being edited, or -1. */
    int currentLight() const;
    /** Selects light `index` in the list (e.g. when it is picked in the scene tree). */
    void setCurrentLight(int index);

    /** Adds a light of the given type near the camera's look-at point; one undo step. */
    void addPointLight();
    void addDirectionalLight();
    /** Adds a rect or disk light just under the scene's top, facing down; one undo step. */
    void addRectLight();
    void addDiskLight();
    /** Removes the current light; one undo step. */
    void removeCurrentLight();

private:
    void onDocumentChanged(const doc::ChangeEvent& event);
    /** Points the list at the model's "Lights" group again (a model reset invalidates the old root). */
    void attachList();
    void loadLight();
    void addLight(doc::LightType type);
    void applyEdit(doc::LightField field, const std::function<void(doc::LightNode&)>& change);

    QPointer<doc::Document> m_document;
    QMetaObject::Connection m_changedConnection;
    SceneTreeModel* m_model = nullptr;
    QListView* m_list = nullptr;
    QPushButton* m_addPoint = nullptr;
    QPushButton* m_addDirectional = nullptr;
    QPushButton* m_addRect = nullptr;
    QPushButton* m_addDisk = nullptr;
    QPushButton* m_remove = nullptr;
    QWidget* m_editors = nullptr;
    QLineEdit* m_name = nullptr;
    QComboBox* m_type = nullptr;
    QLabel* m_positionLabel = nullptr;
    QWidget* m_positionRow = nullptr;
    std::array<QDoubleSpinBox*, 3> m_position {};
    QLabel* m_directionLabel = nullptr;
    QWidget* m_directionRow = nullptr;
    std::array<QDoubleSpinBox*, 3> m_direction {};
    ColorButton* m_color = nullptr;
    QLabel* m_intensityLabel = nullptr; ///< "Intensity", or "Radiance" for rects and disks
    QDoubleSpinBox* m_intensity = nullptr;
    QLabel* m_spotLabel = nullptr;
    QWidget* m_spotRow = nullptr;
    QDoubleSpinBox* m_spotInner = nullptr; ///< degrees from the axis
    QDoubleSpinBox* m_spotOuter = nullptr;
    QLabel* m_radiusLabel = nullptr;
    QDoubleSpinBox* m_radius = nullptr; ///< metres, point and spot lights only
    QLabel* m_angularDiameterLabel = nullptr;
    QDoubleSpinBox* m_angularDiameter = nullptr; ///< degrees, directional lights only
    QLabel* m_areaWidthLabel = nullptr; ///< "Width", or "Diameter" for disks
    QDoubleSpinBox* m_areaWidth = nullptr; ///< metres
    QLabel* m_areaHeightLabel = nullptr;
    QDoubleSpinBox* m_areaHeight = nullptr; ///< metres, rects only
    QLabel* m_areaRotationLabel = nullptr;
    QDoubleSpinBox* m_areaRotation = nullptr; ///< degrees about the direction, rects only
    QCheckBox* m_shadows = nullptr;
    bool m_applying = false; ///< True while our own setLight runs: the editors already show the result.
};

} // namespace vct::ui
