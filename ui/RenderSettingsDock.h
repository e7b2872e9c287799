#pragma once

// Complete type: QPointer<Document> members are destroyed in code moc generates.
#include "document/Document.h"

#include <QDockWidget>
#include <QPointer>

#include <functional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace vct::render {
struct RenderSettings;
}

namespace vct::ui {

/**
 * Every RenderSettings field, grouped as Voxels / Cones / Terms / Output, plus three presets. Each edit
 * builds new settings from the document's current ones and makes one Document::setSettings call; a preset
 * changes several fields in that one call, so it is one undo step.
 */
class RenderSettingsDock : public QDockWidget {
    Q_OBJECT

public:
    enum class Preset { Fast, Balanced, High };

    explicit RenderSettingsDock(QWidget* parent = nullptr);

    /** The dock does not own the document; null disables the editors. */
    void setDocument(doc::Document* document);

    /** Applies a preset to the document as one undo step. */
    void applyPreset(Preset preset);
    /** The fields a preset sets, applied on top of `base` (the rest of `base` is kept). */
    static render::RenderSettings presetSettings(Preset preset, const render::RenderSettings& base);

private:
    void onDocumentChanged(const doc::ChangeEvent& event);
    /** Shows the document's settings without emitting edits. */
    void load();
    void edit(const std::function<void(render::RenderSettings&)>& change);

    QPointer<doc::Document> m_document;
    QMetaObject::Connection m_changedConnection;
    bool m_applying = false;

    QPushButton* m_fast = nullptr;
    QPushButton* m_balanced = nullptr;
    QPushButton* m_high = nullptr;
    QComboBox* m_resolution = nullptr;
    QCheckBox* m_conservative = nullptr;
    QCheckBox* m_anisotropic = nullptr;
    QComboBox* m_bounces = nullptr;
    QComboBox* m_indirectResolution = nullptr;
    QComboBox* m_specularResolution = nullptr;
    QComboBox* m_areaShadowResolution = nullptr;
    QCheckBox* m_irradianceCache = nullptr;
    QComboBox* m_irradianceCell = nullptr;
    QSpinBox* m_coneCount = nullptr;
    QDoubleSpinBox* m_diffuseAperture = nullptr;
    QDoubleSpinBox* m_specularAperture = nullptr;
    QDoubleSpinBox* m_step = nullptr;
    QDoubleSpinBox* m_maxDistance = nullptr;
    QDoubleSpinBox* m_coneOffset = nullptr;
    QCheckBox* m_direct = nullptr;
    QCheckBox* m_indirectDiffuse = nullptr;
    QCheckBox* m_indirectSpecular = nullptr;
    QCheckBox* m_ao = nullptr;
    QCheckBox* m_emission = nullptr;
    QComboBox* m_shadowMap = nullptr;
    QDoubleSpinBox* m_exposure = nullptr;
    QComboBox* m_view = nullptr;
    QLabel* m_problem = nullptr;
};

} // namespace vct::ui
