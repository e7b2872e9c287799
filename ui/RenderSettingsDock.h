#pragma once

// Complete type: QPointer<Document> members are destroyed in code moc generates.
#include "document/Document.h"

#include <QDockWidget>
#include <QHash>
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
 * changes several fields in that one call, so it is one undo step. An edit the settings refuse leaves the
 * document alone and says why where the user is looking: in the refused control's tooltip (shown at once),
 * above the groups, and through settingRefused() in the main window's status bar.
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
    /**
     * Why `settings` cannot be applied, or an empty string. A grid over the voxel budget names its size, the
     * memory it needs and the budget; `source` is the control the edit came from (the budget's own spin box
     * gets a message about the budget).
     */
    QString refusalReason(const render::RenderSettings& settings, const QWidget* source) const;

signals:
    /** An edit from one of the dock's controls was refused, for `reason`; the document is unchanged. */
    void settingRefused(const QString& reason);

private:
    void onDocumentChanged(const doc::ChangeEvent& event);
    /** Shows the document's settings without emitting edits. */
    void load();
    /** Applies the edit from `source`, or refuses it and says why. */
    void edit(QWidget* source, const std::function<void(render::RenderSettings&)>& change);
    void apply(QWidget* source, const render::RenderSettings& next);
    void refuse(QWidget* source, const QString& reason);
    /** Gives refused controls their own tooltips back and hides the message. */
    void clearRefusals();

    QPointer<doc::Document> m_document;
    QMetaObject::Connection m_changedConnection;
    bool m_applying = false;

    QPushButton* m_fast = nullptr;
    QPushButton* m_balanced = nullptr;
    QPushButton* m_high = nullptr;
    QComboBox* m_resolution = nullptr;
    QComboBox* m_gridLevels = nullptr; ///< a dense grid (1), a sparse one (0) or a clipmap's levels (2..)
    QCheckBox* m_conservative = nullptr;
    QCheckBox* m_anisotropic = nullptr;
    QCheckBox* m_dropBackFaces = nullptr;
    QCheckBox* m_enclosedSpace = nullptr;
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
    QDoubleSpinBox* m_bounceStep = nullptr;
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
    QSpinBox* m_budget = nullptr;
    QLabel* m_memoryNeeded = nullptr;
    QLabel* m_problem = nullptr;
    /** The own tooltips of controls that now show a refusal. */
    QHash<QWidget*, QString> m_ownTips;
};

} // namespace vct::ui
