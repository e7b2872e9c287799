#include "RenderSettingsDock.h"

#include "document/Document.h"

#include "scene/RenderSettings.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QToolTip>
#include <QVBoxLayout>

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

namespace vct::ui {

namespace {

using render::DebugView;

// RenderSettings::validate()'s range for voxel_budget_mb.
constexpr int kMinBudgetMiB = 64;
constexpr int kMaxBudgetMiB = 1 << 20;

struct ViewEntry {
    DebugView view;
    const char* label;
};

const ViewEntry kViews[] = {
    { DebugView::Final, QT_TRANSLATE_NOOP("RenderSettingsDock", "Final") },
    { DebugView::Direct, QT_TRANSLATE_NOOP("RenderSettingsDock", "Direct") },
    { DebugView::IndirectDiffuse, QT_TRANSLATE_NOOP("RenderSettingsDock", "Indirect diffuse") },
    { DebugView::IndirectSpecular, QT_TRANSLATE_NOOP("RenderSettingsDock", "Indirect specular") },
    { DebugView::AmbientOcclusion, QT_TRANSLATE_NOOP("RenderSettingsDock", "Ambient occlusion") },
    { DebugView::Albedo, QT_TRANSLATE_NOOP("RenderSettingsDock", "Albedo") },
    { DebugView::Normal, QT_TRANSLATE_NOOP("RenderSettingsDock", "Normal") },
    { DebugView::Emission, QT_TRANSLATE_NOOP("RenderSettingsDock", "Emission") },
};

// Settings compare by their key=value text: RenderSettings has no operator== and the text is what a
// project file stores, so "unchanged" means the same thing here and there.
bool sameSettings(const render::RenderSettings& a, const render::RenderSettings& b)
{
    return a.describe() == b.describe();
}

QDoubleSpinBox* makeSpin(
    double min, double max, int decimals, double step, const QString& suffix, const QString& tip)
{
    auto* spin = new QDoubleSpinBox;
    spin->setRange(min, max);
    spin->setDecimals(decimals);
    spin->setSingleStep(step);
    spin->setSuffix(suffix);
    spin->setToolTip(tip);
    spin->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    return spin;
}

QCheckBox* makeCheck(const QString& text, const QString& tip)
{
    auto* check = new QCheckBox(text);
    check->setToolTip(tip);
    return check;
}

/** As the budget reads: whole MiB below a GiB, GiB to one decimal from there. */
QString memoryText(std::uint64_t bytes)
{
    constexpr std::uint64_t kMiB = std::uint64_t(1) << 20;
    constexpr std::uint64_t kGiB = kMiB << 10;
    if (bytes < kGiB)
        return QString::number((bytes + kMiB - 1) / kMiB) + QStringLiteral(" MiB");
    return QString::number(double(bytes) / double(kGiB), 'f', 1) + QStringLiteral(" GiB");
}

void setSpinValue(QDoubleSpinBox* spin, double value)
{
    if (std::abs(spin->value() - value) > 1e-9)
        spin->setValue(value);
}

/** Selects the item whose data is `value`, adding it when a project carries a value the list lacks. */
void selectIntItem(QComboBox* combo, int value, const QString& text)
{
    int row = combo->findData(value);
    if (row < 0) {
        combo->addItem(text, value);
        row = combo->count() - 1;
    }
    combo->setCurrentIndex(row);
}

} // namespace

RenderSettingsDock::RenderSettingsDock(QWidget* parent)
    : QDockWidget(tr("Render settings"), parent)
{
    setObjectName(QStringLiteral("RenderSettingsDock"));

    m_fast = new QPushButton(tr("Fast"));
    m_fast->setObjectName(QStringLiteral("presetFast"));
    m_fast->setToolTip(tr("64³ voxels, 5 cones of 30°, indirect light at quarter resolution"));
    m_balanced = new QPushButton(tr("Balanced"));
    m_balanced->setObjectName(QStringLiteral("presetBalanced"));
    m_balanced->setToolTip(
        tr("The default: 128³ anisotropic voxels, 7 cones of 22°, indirect light at quarter resolution"));
    m_high = new QPushButton(tr("High"));
    m_high->setObjectName(QStringLiteral("presetHigh"));
    m_high->setToolTip(tr("Balanced with 13 cones of 20° and a finer specular grid"));
    auto* presets = new QHBoxLayout;
    presets->setContentsMargins(0, 0, 0, 0);
    presets->addWidget(new QLabel(tr("Preset")));
    for (QPushButton* button : { m_fast, m_balanced, m_high }) {
        // Checked shows which preset the current values match; clicking applies it.
        button->setCheckable(true);
        presets->addWidget(button);
    }

    m_resolution = new QComboBox;
    m_resolution->setObjectName(QStringLiteral("voxelResolutionCombo"));
    // Not arg("%1³"): QString::arg reads the superscript digit as a placeholder number.
    for (int res = 32; res <= 512; res *= 2)
        m_resolution->addItem(QString::number(res) + QStringLiteral("³"), res);
    m_resolution->setToolTip(
        tr("Voxel grid cells per side. Memory and voxelization time grow with the cube."));
    m_gridLevels = new QComboBox;
    m_gridLevels->setObjectName(QStringLiteral("gridLevelsCombo"));
    m_gridLevels->addItem(tr("One grid"), 1);
    // 0: one grid whose level 0 keeps only the bricks holding surface (voxel_mode=sparse).
    m_gridLevels->addItem(tr("One grid, sparse"), 0);
    for (int levels = 2; levels <= 4; ++levels)
        m_gridLevels->addItem(tr("Clipmap, %1 levels").arg(levels), levels);
    m_gridLevels->setToolTip(tr(
        "One grid around the scene; the same grid sparse, storing only the 8³ bricks that hold surface "
        "(for fine grids around large, mostly empty scenes); or a clipmap: nested grids of this "
        "resolution, each finer one half as wide and following the camera, for finer voxels near it at one "
        "grid's memory per level (voxel_mode, clip_levels)"));
    m_conservative = makeCheck(tr("Conservative voxelization"),
        tr("Mark every voxel a triangle touches, so thin and oblique walls leave no holes"));
    m_conservative->setObjectName(QStringLiteral("conservativeCheck"));
    m_anisotropic = makeCheck(tr("Anisotropic mips"),
        tr("Six direction-dependent mip chains: thin walls stay opaque to wide cones, at three lookups per "
           "coarse sample"));
    m_anisotropic->setObjectName(QStringLiteral("anisotropicCheck"));
    m_dropBackFaces = makeCheck(tr("Drop back faces"),
        tr("The anisotropic mips leave out surfaces facing the way a cone travels, so a surface does not "
           "light or shade the cones leaving it; a lone one-sided quad is see-through from behind "
           "(drop_back_faces)"));
    m_dropBackFaces->setObjectName(QStringLiteral("dropBackFacesCheck"));
    m_enclosedSpace = makeCheck(tr("Close enclosed space"),
        tr("Where no light can leave (a closed room), diffuse cones count what walls one voxel "
           "thick let through as the walls' own light, so a closed room keeps its light (enclosed_space)"));
    m_enclosedSpace->setObjectName(QStringLiteral("enclosedSpaceCheck"));
    m_bounces = new QComboBox;
    m_bounces->setObjectName(QStringLiteral("bouncesCombo"));
    m_bounces->addItem(tr("Converged (all)"), render::RenderSettings::kConvergedBounces);
    m_bounces->addItem(tr("1 (one gathered)"), 1);
    m_bounces->addItem(tr("2"), 2);
    m_bounces->addItem(tr("4"), 4);
    m_bounces->setToolTip(
        tr("Light bounces the voxels carry. Converged iterates until the light settles (the view "
           "keeps refining while idle; the stats panel shows the iterations), as a closed room "
           "needs; each iteration gathers once per occupied cell when the lighting changes"));
    m_indirectResolution = new QComboBox;
    m_indirectResolution->setObjectName(QStringLiteral("indirectResolutionCombo"));
    m_indirectResolution->addItem(tr("Full"), 1);
    m_indirectResolution->addItem(tr("Half"), 2);
    m_indirectResolution->addItem(tr("Quarter"), 4);
    m_irradianceCache = makeCheck(tr("Irradiance cache"),
        tr("Gather the diffuse cones once per surface cell when the light changes, and look them up per "
           "pixel: "
           "camera moves trace no diffuse cones; light edits cost a gather over the whole grid"));
    m_irradianceCache->setObjectName(QStringLiteral("irradianceCacheCheck"));
    m_irradianceCell = new QComboBox;
    m_irradianceCell->setObjectName(QStringLiteral("irradianceCellCombo"));
    for (int cell : { 1, 2, 4 })
        m_irradianceCell->addItem(QString::number(cell) + QStringLiteral("³ ") + tr("voxels"), cell);
    m_irradianceCell->setToolTip(tr("Voxels per cache cell: larger cells gather faster and blur more"));
    m_indirectResolution->setToolTip(tr("Cones are traced for one pixel in N×N and upsampled with depth- and "
                                        "normal-aware weights"));
    m_areaShadowResolution = new QComboBox;
    m_areaShadowResolution->setObjectName(QStringLiteral("areaShadowResolutionCombo"));
    m_areaShadowResolution->addItem(tr("Full"), 1);
    m_areaShadowResolution->addItem(tr("Half"), 2);
    m_areaShadowResolution->addItem(tr("Quarter"), 4);
    m_areaShadowResolution->setToolTip(
        tr("The shadow cones of emissive surfaces (area lights) are traced for one "
           "pixel in N×N and upsampled; their unshadowed light stays exact per pixel"));
    m_specularResolution = new QComboBox;
    m_specularResolution->setObjectName(QStringLiteral("specularResolutionCombo"));
    m_specularResolution->addItem(tr("Full"), 1);
    m_specularResolution->addItem(tr("Half"), 2);
    m_specularResolution->addItem(tr("Quarter"), 4);
    m_specularResolution->addItem(tr("Eighth"), 8);
    m_specularResolution->setToolTip(
        tr("The specular cone is traced for one pixel in N×N of glossy surfaces and "
           "upsampled like the diffuse cones"));

    m_coneCount = new QSpinBox;
    m_coneCount->setObjectName(QStringLiteral("diffuseConeCount"));
    m_coneCount->setRange(1, 32);
    m_coneCount->setToolTip(tr("Diffuse cones per pixel; 5 = one along the normal and four tilted 45°"));
    m_diffuseAperture
        = makeSpin(1.0, 179.0, 1, 5.0, QStringLiteral("°"), tr("Full angle of each diffuse cone"));
    m_diffuseAperture->setObjectName(QStringLiteral("diffuseAperture"));
    m_specularAperture = makeSpin(1.0, 179.0, 1, 1.0, QStringLiteral("°"),
        tr("Narrowest specular cone; glossier lobes are clamped to it"));
    m_specularAperture->setObjectName(QStringLiteral("specularAperture"));
    m_step = makeSpin(0.05, 10.0, 2, 0.05, QString(),
        tr("β: step = cone diameter × β. Smaller is more accurate and slower."));
    m_step->setObjectName(QStringLiteral("stepFactor"));
    // At most RenderSettings::validate's 8; a quarter already steps four times finer than the pixels' cones.
    m_bounceStep = makeSpin(0.25, 8.0, 2, 0.25, QStringLiteral("×"),
        tr("The bounce solve's cone steps as a multiple of β: its light is interpolated between cells and "
           "summed over bounces, so longer steps cost little accuracy. 1 steps as the pixels' cones do."));
    m_bounceStep->setObjectName(QStringLiteral("bounceStep"));
    m_maxDistance = makeSpin(0.0, 10000.0, 2, 0.1, QStringLiteral(" m"),
        tr("Cone length in metres; \"auto\" uses the voxel grid's diagonal"));
    m_maxDistance->setObjectName(QStringLiteral("maxDistance"));
    // The minimum stands for "auto" (stored as a negative distance): a zero-length cone means nothing.
    m_maxDistance->setSpecialValueText(tr("auto"));
    m_coneOffset = makeSpin(0.0, 10.0, 2, 0.1, tr(" voxels"),
        tr("Cone origins start this far along the normal, so a surface does not occlude itself"));
    m_coneOffset->setObjectName(QStringLiteral("coneOffset"));

    m_direct = makeCheck(tr("Direct light"), tr("Light arriving straight from the lights, with shadow maps"));
    m_indirectDiffuse
        = makeCheck(tr("Indirect diffuse"), tr("One-bounce diffuse light from the diffuse cones"));
    m_indirectSpecular
        = makeCheck(tr("Indirect specular"), tr("The specular cone, on glossy materials only"));
    m_ao = makeCheck(tr("Ambient occlusion"), tr("Occlusion from the diffuse cones; view it with View = AO"));
    m_emission = makeCheck(tr("Emission"), tr("Emissive materials glow and light their surroundings"));
    m_direct->setObjectName(QStringLiteral("directCheck"));
    m_indirectDiffuse->setObjectName(QStringLiteral("indirectDiffuseCheck"));
    m_indirectSpecular->setObjectName(QStringLiteral("indirectSpecularCheck"));
    m_ao->setObjectName(QStringLiteral("aoCheck"));
    m_emission->setObjectName(QStringLiteral("emissionCheck"));

    m_shadowMap = new QComboBox;
    m_shadowMap->setObjectName(QStringLiteral("shadowMapCombo"));
    for (int size = 256; size <= 4096; size *= 2)
        m_shadowMap->addItem(QString::number(size) + QStringLiteral("²"), size);
    m_shadowMap->setToolTip(tr("Shadow map texels per side (per cube face for point lights)"));
    m_exposure = makeSpin(0.01, 100.0, 2, 0.1, QStringLiteral("×"),
        tr("Multiplier before the filmic curve (8-bit output only)"));
    m_exposure->setObjectName(QStringLiteral("exposure"));
    m_exposure->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
    m_view = new QComboBox;
    m_view->setObjectName(QStringLiteral("viewCombo"));
    for (const ViewEntry& entry : kViews)
        m_view->addItem(tr(entry.label), int(entry.view));
    m_view->setToolTip(tr("Show one term of the image instead of the final result"));

    m_budget = new QSpinBox;
    m_budget->setObjectName(QStringLiteral("voxelBudget"));
    m_budget->setRange(kMinBudgetMiB, kMaxBudgetMiB);
    m_budget->setSingleStep(512);
    m_budget->setSuffix(QStringLiteral(" MiB"));
    // Typing 8192 passes through 8, 81 and 819, each a budget the grid would not fit: apply on Enter only.
    m_budget->setKeyboardTracking(false);
    m_budget->setToolTip(
        tr("Most memory the voxel textures may take (voxel_budget_mb). A grid that needs more "
           "is refused instead of failing in the GL driver; raise it where the GPU has the "
           "memory."));
    m_budget->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    m_memoryNeeded = new QLabel;
    m_memoryNeeded->setObjectName(QStringLiteral("voxelMemoryNeeded"));
    m_memoryNeeded->setToolTip(
        tr("What the voxel textures of the current settings take: the grid, anisotropic "
           "mips, bounces and the irradiance cache all add to it"));

    m_problem = new QLabel;
    m_problem->setObjectName(QStringLiteral("settingsProblem"));
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #d08020;"));
    m_problem->hide();

    const auto group = [](const QString& title) {
        auto* box = new QGroupBox(title);
        auto* form = new QFormLayout(box);
        form->setContentsMargins(6, 4, 6, 4);
        form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
        return std::pair { box, form };
    };
    auto [voxels, voxelForm] = group(tr("Voxels"));
    voxelForm->addRow(tr("Resolution"), m_resolution);
    voxelForm->addRow(tr("Grids"), m_gridLevels);
    voxelForm->addRow(m_conservative);
    voxelForm->addRow(m_anisotropic);
    voxelForm->addRow(m_dropBackFaces);
    voxelForm->addRow(m_enclosedSpace);
    voxelForm->addRow(tr("Bounces"), m_bounces);
    auto* budgetRow = new QHBoxLayout;
    budgetRow->addWidget(m_budget, 1);
    budgetRow->addWidget(m_memoryNeeded);
    voxelForm->addRow(tr("Memory budget"), budgetRow);
    auto [cones, coneForm] = group(tr("Cones"));
    coneForm->addRow(tr("Diffuse cones"), m_coneCount);
    coneForm->addRow(tr("Diffuse aperture"), m_diffuseAperture);
    coneForm->addRow(tr("Specular aperture"), m_specularAperture);
    coneForm->addRow(tr("Step factor β"), m_step);
    coneForm->addRow(tr("Bounce step"), m_bounceStep);
    coneForm->addRow(tr("Max distance"), m_maxDistance);
    coneForm->addRow(tr("Cone offset"), m_coneOffset);
    coneForm->addRow(tr("Indirect resolution"), m_indirectResolution);
    coneForm->addRow(tr("Specular resolution"), m_specularResolution);
    coneForm->addRow(tr("Area shadows"), m_areaShadowResolution);
    coneForm->addRow(m_irradianceCache);
    coneForm->addRow(tr("Cache cell"), m_irradianceCell);
    auto [terms, termForm] = group(tr("Terms"));
    for (QCheckBox* check : { m_direct, m_indirectDiffuse, m_indirectSpecular, m_ao, m_emission })
        termForm->addRow(check);
    auto [output, outputForm] = group(tr("Output"));
    outputForm->addRow(tr("Shadow maps"), m_shadowMap);
    outputForm->addRow(tr("Exposure"), m_exposure);
    outputForm->addRow(tr("View"), m_view);

    auto* body = new QWidget;
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(presets);
    // At the top: below the groups it sat under the fold of a dock of ordinary height.
    layout->addWidget(m_problem);
    for (QGroupBox* box : { voxels, cones, terms, output })
        layout->addWidget(box);
    layout->addStretch();
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(body);
    setWidget(scroll);

    connect(m_fast, &QPushButton::clicked, this, [this] { applyPreset(Preset::Fast); });
    connect(m_balanced, &QPushButton::clicked, this, [this] { applyPreset(Preset::Balanced); });
    connect(m_high, &QPushButton::clicked, this, [this] { applyPreset(Preset::High); });

    const auto bindCombo = [this](QComboBox* combo, int render::RenderSettings::*field) {
        connect(combo, &QComboBox::currentIndexChanged, this, [this, combo, field](int row) {
            if (row < 0)
                return;
            const int value = combo->itemData(row).toInt();
            edit(combo, [&](render::RenderSettings& s) { s.*field = value; });
        });
    };
    bindCombo(m_resolution, &render::RenderSettings::voxelResolution);
    connect(m_gridLevels, &QComboBox::currentIndexChanged, this, [this](int row) {
        if (row < 0)
            return;
        const int levels = m_gridLevels->itemData(row).toInt();
        edit(m_gridLevels, [&](render::RenderSettings& s) {
            s.voxelMode = levels > 1 ? render::VoxelMode::Clipmap
                : levels == 0        ? render::VoxelMode::Sparse
                                     : render::VoxelMode::Dense;
            if (levels > 1)
                s.clipLevels = levels;
        });
    });
    bindCombo(m_shadowMap, &render::RenderSettings::shadowMapSize);
    bindCombo(m_bounces, &render::RenderSettings::bounces);
    bindCombo(m_indirectResolution, &render::RenderSettings::indirectDivisor);
    bindCombo(m_specularResolution, &render::RenderSettings::specularDivisor);
    bindCombo(m_areaShadowResolution, &render::RenderSettings::areaShadowDivisor);
    bindCombo(m_irradianceCell, &render::RenderSettings::irradianceCellSize);
    connect(m_view, &QComboBox::currentIndexChanged, this, [this](int row) {
        if (row < 0)
            return;
        const auto view = DebugView(m_view->itemData(row).toInt());
        edit(m_view, [view](render::RenderSettings& s) { s.view = view; });
    });
    connect(m_coneCount, &QSpinBox::valueChanged, this,
        [this](int v) { edit(m_coneCount, [v](render::RenderSettings& s) { s.diffuseConeCount = v; }); });
    connect(m_budget, &QSpinBox::valueChanged, this,
        [this](int v) { edit(m_budget, [v](render::RenderSettings& s) { s.voxelBudgetMiB = v; }); });

    const auto bindSpin = [this](QDoubleSpinBox* spin, float render::RenderSettings::*field) {
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this, spin, field](double v) {
            edit(spin, [&](render::RenderSettings& s) { s.*field = float(v); });
        });
    };
    bindSpin(m_diffuseAperture, &render::RenderSettings::diffuseApertureDeg);
    bindSpin(m_specularAperture, &render::RenderSettings::specularApertureDeg);
    bindSpin(m_step, &render::RenderSettings::stepFactor);
    bindSpin(m_bounceStep, &render::RenderSettings::bounceStepScale);
    bindSpin(m_coneOffset, &render::RenderSettings::coneOffsetVoxels);
    bindSpin(m_exposure, &render::RenderSettings::exposure);
    connect(m_maxDistance, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        edit(m_maxDistance, [&](render::RenderSettings& s) {
            s.maxDistance = v <= m_maxDistance->minimum() ? -1.0f : float(v);
        });
    });

    const auto bindCheck = [this](QCheckBox* check, bool render::RenderSettings::*field) {
        connect(check, &QCheckBox::toggled, this, [this, check, field](bool on) {
            edit(check, [&](render::RenderSettings& s) { s.*field = on; });
        });
    };
    bindCheck(m_conservative, &render::RenderSettings::conservativeVoxelization);
    bindCheck(m_anisotropic, &render::RenderSettings::anisotropicMips);
    bindCheck(m_dropBackFaces, &render::RenderSettings::dropBackFaces);
    bindCheck(m_enclosedSpace, &render::RenderSettings::enclosedSpace);
    bindCheck(m_irradianceCache, &render::RenderSettings::irradianceCache);
    bindCheck(m_direct, &render::RenderSettings::direct);
    bindCheck(m_indirectDiffuse, &render::RenderSettings::indirectDiffuse);
    bindCheck(m_indirectSpecular, &render::RenderSettings::indirectSpecular);
    bindCheck(m_ao, &render::RenderSettings::ambientOcclusion);
    bindCheck(m_emission, &render::RenderSettings::emission);

    setDocument(nullptr);
}

void RenderSettingsDock::setDocument(doc::Document* document)
{
    disconnect(m_changedConnection);
    m_document = document;
    if (m_document)
        m_changedConnection
            = connect(m_document, &doc::Document::changed, this, &RenderSettingsDock::onDocumentChanged);
    clearRefusals();
    load();
}

render::RenderSettings RenderSettingsDock::presetSettings(Preset preset, const render::RenderSettings& base)
{
    render::RenderSettings s = base;
    // From the accuracy/time study (docs/ACCURACY.md, "Recommended defaults and presets"): only settings on
    // or next to the frontier in both the Cornell box and the atrium. Finer grids were measured to cost more
    // without lowering the error, so no preset uses them.
    s.diffuseConeCount = 7;
    s.diffuseApertureDeg = 22.0f;
    s.dropBackFaces = true;
    s.enclosedSpace = true;
    s.stepFactor = 1.0f;
    s.bounceStepScale = 2.0f;
    s.bounceCellSize = 4;
    s.higherBounceCellSize = 8;
    switch (preset) {
    case Preset::Fast:
        // A coarse grid with isotropic mips: the cheapest full frame that is still on the frontier. Dense, as
        // isotropic mips need (a 64^3 grid gains little from bricks).
        s.voxelResolution = 64;
        s.anisotropicMips = false;
        if (s.voxelMode == render::VoxelMode::Sparse)
            s.voxelMode = render::VoxelMode::Dense;
        // Box mips leak most of what narrower cones would add: fewer, wider cones measure the same, for less.
        s.diffuseConeCount = 5;
        s.diffuseApertureDeg = 30.0f;
        s.bounces = 1; // box mips leak most of a gather: further bounces add little (docs/ACCURACY.md)
        s.indirectDivisor = 4;
        s.specularDivisor = 8;
        break;
    case Preset::Balanced:
        // The defaults of RenderSettings.
        s.voxelResolution = 128;
        s.anisotropicMips = true;
        s.bounces = render::RenderSettings::kConvergedBounces;
        s.indirectDivisor = 4;
        s.specularDivisor = 8;
        break;
    case Preset::High:
        // Balanced with 13 cones of 20 degrees and a finer specular grid: closer to the references of the
        // point-lit Cornell box and the atrium (docs/ACCURACY.md, "Recommended defaults and presets"). Cells
        // of 2^3 voxels for the bounce gather, High before, cost 1.5-1.7 times for no gain.
        s.voxelResolution = 128;
        s.anisotropicMips = true;
        s.bounces = render::RenderSettings::kConvergedBounces;
        s.diffuseConeCount = 13;
        s.diffuseApertureDeg = 20.0f;
        s.indirectDivisor = 4;
        // Sharp reflections of nearby edges keep more of their edge at the finer specular grid.
        s.specularDivisor = 4;
        break;
    }
    return s;
}

void RenderSettingsDock::applyPreset(Preset preset)
{
    if (!m_document)
        return;
    QPushButton* button = preset == Preset::Fast ? m_fast : preset == Preset::Balanced ? m_balanced : m_high;
    // A budget lowered below what the preset's grid needs refuses the preset like any other edit.
    apply(button, presetSettings(preset, m_document->state().settings));
    load(); // The preset buttons' checked state follows the values, whether or not anything changed.
}

QString RenderSettingsDock::refusalReason(const render::RenderSettings& settings, const QWidget* source) const
{
    const std::string problem = settings.validate();
    if (problem.empty())
        return {};
    render::RenderSettings unlimited = settings;
    unlimited.voxelBudgetMiB = kMaxBudgetMiB;
    const bool overBudget = settings.voxelBudgetMiB >= kMinBudgetMiB
        && settings.voxelBudgetMiB <= kMaxBudgetMiB && unlimited.validate().empty();
    if (!overBudget)
        return QString::fromStdString(problem);
    // In the dock's words (grid size, GiB) rather than validate()'s key=value ones; the key still names the
    // setting for project files and vct-render --set.
    const QString grid = QString::number(settings.voxelResolution) + QStringLiteral("³");
    const QString needed = memoryText(settings.voxelMemoryBytes());
    const QString budget = memoryText(std::uint64_t(settings.voxelBudgetMiB) << 20);
    if (source == m_budget)
        return tr(
            "A voxel budget of %1 is too small: the %2 grid needs %3 of voxel textures (voxel_budget_mb)")
            .arg(budget, grid, needed);
    return tr("%1 needs %2 of voxel textures; the budget is %3 (voxel_budget_mb). Raise the memory budget "
              "if the GPU has the memory.")
        .arg(grid, needed, budget);
}

void RenderSettingsDock::edit(QWidget* source, const std::function<void(render::RenderSettings&)>& change)
{
    if (!m_document)
        return;
    render::RenderSettings next = m_document->state().settings;
    change(next);
    apply(source, next);
}

void RenderSettingsDock::apply(QWidget* source, const render::RenderSettings& next)
{
    if (const QString reason = refusalReason(next, source); !reason.isEmpty()) {
        refuse(source, reason);
        load(); // The refused control shows the document's value again.
        return;
    }
    clearRefusals();
    if (sameSettings(m_document->state().settings, next))
        return;
    m_applying = true;
    m_document->setSettings(next);
    m_applying = false;
    load(); // Cheap, and keeps the preset buttons in step; equal values are not rewritten.
}

void RenderSettingsDock::refuse(QWidget* source, const QString& reason)
{
    m_problem->setText(reason);
    m_problem->show();
    if (source) {
        if (!m_ownTips.contains(source))
            m_ownTips.insert(source, source->toolTip());
        const QString own = m_ownTips.value(source);
        const QString tip
            = tr("Refused: %1").arg(reason) + (own.isEmpty() ? QString() : QStringLiteral("\n\n") + own);
        source->setToolTip(tip);
        // Shown now, under the control the user just touched: hovering is not how anyone learns of a refusal.
        if (source->isVisible())
            QToolTip::showText(source->mapToGlobal(QPoint(0, source->height())), tip, source);
    }
    emit settingRefused(reason);
}

void RenderSettingsDock::clearRefusals()
{
    for (auto it = m_ownTips.cbegin(); it != m_ownTips.cend(); ++it)
        it.key()->setToolTip(it.value());
    m_ownTips.clear();
    m_problem->hide();
}

void RenderSettingsDock::onDocumentChanged(const doc::ChangeEvent& event)
{
    using Kind = doc::ChangeEvent::Kind;
    if (event.kind == Kind::Reset)
        clearRefusals(); // about the settings of the document that was replaced
    if (!m_applying && (event.kind == Kind::Settings || event.kind == Kind::Reset))
        load();
}

void RenderSettingsDock::load()
{
    widget()->setEnabled(m_document);
    if (!m_document)
        return;
    const render::RenderSettings& s = m_document->state().settings;

    const QList<QWidget*> editors { m_resolution, m_gridLevels, m_conservative, m_anisotropic,
        m_dropBackFaces, m_enclosedSpace, m_bounces, m_indirectResolution, m_specularResolution,
        m_areaShadowResolution, m_irradianceCache, m_irradianceCell, m_coneCount, m_diffuseAperture,
        m_specularAperture, m_step, m_bounceStep, m_maxDistance, m_coneOffset, m_direct, m_indirectDiffuse,
        m_indirectSpecular, m_ao, m_emission, m_shadowMap, m_exposure, m_view, m_budget, m_fast, m_balanced,
        m_high };
    std::vector<std::unique_ptr<QSignalBlocker>> blockers;
    for (QWidget* w : editors)
        blockers.push_back(std::make_unique<QSignalBlocker>(w));

    selectIntItem(m_resolution, s.voxelResolution, QString::number(s.voxelResolution) + QStringLiteral("³"));
    selectIntItem(m_gridLevels, s.voxelMode == render::VoxelMode::Sparse ? 0 : s.gridLevels(),
        tr("Clipmap, %1 levels").arg(s.gridLevels()));
    m_conservative->setChecked(s.conservativeVoxelization);
    m_anisotropic->setChecked(s.anisotropicMips);
    // A sparse grid has no box mip chain to fall back to (voxel_mode=sparse needs anisotropic=on).
    m_anisotropic->setEnabled(s.voxelMode != render::VoxelMode::Sparse);
    m_dropBackFaces->setChecked(s.dropBackFaces);
    m_dropBackFaces->setEnabled(s.anisotropicMips); // only the directional chains know which way cones go
    m_enclosedSpace->setChecked(s.enclosedSpace);
    selectIntItem(m_bounces, s.bounces, QString::number(s.bounces));
    m_irradianceCache->setChecked(s.irradianceCache);
    selectIntItem(m_irradianceCell, s.irradianceCellSize, QString::number(s.irradianceCellSize));
    m_irradianceCell->setEnabled(s.irradianceCache);
    selectIntItem(
        m_indirectResolution, s.indirectDivisor, QStringLiteral("1/") + QString::number(s.indirectDivisor));
    selectIntItem(
        m_specularResolution, s.specularDivisor, QStringLiteral("1/") + QString::number(s.specularDivisor));
    selectIntItem(m_areaShadowResolution, s.areaShadowDivisor,
        QStringLiteral("1/") + QString::number(s.areaShadowDivisor));
    if (m_coneCount->value() != s.diffuseConeCount)
        m_coneCount->setValue(s.diffuseConeCount);
    setSpinValue(m_diffuseAperture, double(s.diffuseApertureDeg));
    setSpinValue(m_specularAperture, double(s.specularApertureDeg));
    setSpinValue(m_step, double(s.stepFactor));
    setSpinValue(m_bounceStep, double(s.bounceStepScale));
    setSpinValue(m_maxDistance, s.maxDistance < 0.0f ? m_maxDistance->minimum() : double(s.maxDistance));
    setSpinValue(m_coneOffset, double(s.coneOffsetVoxels));
    m_direct->setChecked(s.direct);
    m_indirectDiffuse->setChecked(s.indirectDiffuse);
    m_indirectSpecular->setChecked(s.indirectSpecular);
    m_ao->setChecked(s.ambientOcclusion);
    m_emission->setChecked(s.emission);
    selectIntItem(m_shadowMap, s.shadowMapSize, QString::number(s.shadowMapSize) + QStringLiteral("²"));
    setSpinValue(m_exposure, double(s.exposure));
    m_view->setCurrentIndex(m_view->findData(int(s.view)));
    if (m_budget->value() != s.voxelBudgetMiB)
        m_budget->setValue(s.voxelBudgetMiB);
    // A sparse grid's pools depend on the scene's surfaces: the renderer counts them once made.
    m_memoryNeeded->setText(s.voxelMode == render::VoxelMode::Sparse
            ? tr("needs %1 and the bricks holding surface").arg(memoryText(s.voxelMemoryBytes()))
            : tr("needs %1").arg(memoryText(s.voxelMemoryBytes())));

    m_fast->setChecked(sameSettings(s, presetSettings(Preset::Fast, s)));
    m_balanced->setChecked(sameSettings(s, presetSettings(Preset::Balanced, s)));
    m_high->setChecked(sameSettings(s, presetSettings(Preset::High, s)));
}

} // namespace vct::ui
