#include "MaterialDock.h"

#include "ColorButton.h"

#include "document/Document.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QVBoxLayout>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>

namespace vct::ui {

namespace {

float maxComponent(const glm::vec3& v)
{
    return std::max({ v.x, v.y, v.z });
}

bool nearlyEqual(const glm::vec3& a, const glm::vec3& b)
{
    const glm::vec3 d = glm::abs(a - b);
    return maxComponent(d) <= 1e-5f * std::max(1.0f, maxComponent(glm::abs(b)));
}

void setSpinValue(QDoubleSpinBox* spin, double value)
{
    // Re-setting an equal value would rewrite the text under the cursor while the user types.
    if (std::abs(spin->value() - value) > 1e-9) {
        const QSignalBlocker block(spin);
        spin->setValue(value);
    }
}

QDoubleSpinBox* makeSpin(double min, double max, int decimals, const QString& suffix, const QString& tip)
{
    auto* spin = new QDoubleSpinBox;
    spin->setRange(min, max);
    spin->setDecimals(decimals);
    spin->setSuffix(suffix);
    spin->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
    spin->setToolTip(tip);
    spin->setKeyboardTracking(true);
    spin->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    return spin;
}

} // namespace

MaterialDock::MaterialDock(QWidget* parent)
    : QDockWidget(tr("Material"), parent)
{
    setObjectName(QStringLiteral("MaterialDock"));
    auto* body = new QWidget(this);

    m_combo = new QComboBox;
    m_combo->setObjectName(QStringLiteral("materialCombo"));
    m_combo->setToolTip(tr("Material being edited; follows the selected node"));
    m_combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_usage = new QLabel;
    m_usage->setObjectName(QStringLiteral("materialUsage"));
    m_usage->setWordWrap(true);
    m_usage->setForegroundRole(QPalette::PlaceholderText);

    m_albedo = new ColorButton;
    m_albedo->setObjectName(QStringLiteral("albedoButton"));
    m_albedo->setDialogTitle(tr("Albedo"));
    m_texture = new QLabel;
    m_texture->setObjectName(QStringLiteral("albedoTexture"));
    m_texture->setToolTip(tr("An albedo texture (sRGB) multiplies the albedo colour"));

    m_doubleSided = new QCheckBox(tr("Double-sided"));
    m_doubleSided->setObjectName(QStringLiteral("doubleSidedCheck"));
    m_doubleSided->setToolTip(
        tr("Seen from both sides. Off: front faces only; back faces are left out of the "
           "image and of shadows, which draws closed models faster"));
    m_emissive = new QCheckBox(tr("Emissive"));
    m_emissive->setObjectName(QStringLiteral("emissiveCheck"));
    m_emissive->setToolTip(tr("Emits light from the front face: radiance = colour × strength"));
    m_emissionColor = new ColorButton;
    m_emissionColor->setObjectName(QStringLiteral("emissionColorButton"));
    m_emissionColor->setDialogTitle(tr("Emission colour"));
    m_strength = makeSpin(0.0, 1.0e6, 3, QStringLiteral(" W/(m²·sr)"),
        tr("Emitted radiance per unit of colour, W/(m²·sr); the Cornell box light is about 17"));
    m_strength->setObjectName(QStringLiteral("emissionStrength"));
    m_strength->setValue(1.0);
    m_emissionColor->setColor(glm::vec3(1.0f));

    m_specular = new ColorButton;
    m_specular->setObjectName(QStringLiteral("specularButton"));
    m_specular->setDialogTitle(tr("Specular"));
    m_specular->setToolTip(tr("Specular reflectance, linear RGB; albedo + specular should not exceed 1"));
    m_shininess = makeSpin(0.0, 100000.0, 1, QString(),
        tr("Phong exponent of the glossy lobe: 0 = matte (no specular cone), ~10 = broad sheen, "
           "~100 = glossy, 1000+ = near mirror. The lobe is clamped to the specular aperture."));
    m_shininess->setObjectName(QStringLiteral("shininessSpin"));
    m_shininess->setSpecialValueText(tr("0 (matte)"));

    m_warning = new QLabel;
    m_warning->setObjectName(QStringLiteral("energyWarning"));
    m_warning->setWordWrap(true);
    m_warning->setText(
        tr("⚠ Albedo + specular exceeds 1: the surface reflects more light than it receives."));
    m_warning->setStyleSheet(QStringLiteral("color: #d08020;"));
    m_warning->hide();

    auto* form = new QFormLayout;
    form->setContentsMargins(0, 0, 0, 0);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    form->addRow(tr("Material"), m_combo);
    form->addRow(QString(), m_usage);
    form->addRow(tr("Albedo"), m_albedo);
    form->addRow(tr("Texture"), m_texture);
    form->addRow(QString(), m_emissive);
    form->addRow(tr("Emission"), m_emissionColor);
    form->addRow(tr("Strength"), m_strength);
    form->addRow(tr("Specular"), m_specular);
    form->addRow(tr("Shininess"), m_shininess);
    form->addRow(QString(), m_doubleSided);

    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(form);
    layout->addWidget(m_warning);
    layout->addStretch();
    setWidget(body);

    using Field = doc::MaterialField;
    const auto edit = [this](Field field, auto change) {
        if (!m_document || m_material < 0 || m_material >= int(m_document->state().materials.size()))
            return;
        render::Material material = m_document->state().materials[std::size_t(m_material)];
        change(material);
        m_applying = true;
        m_document->setMaterial(m_material, material, field);
        m_applying = false;
        updateWarning();
    };

    connect(m_combo, &QComboBox::currentIndexChanged, this, [this](int row) {
        if (row < 0)
            return;
        setCurrentMaterial(m_combo->itemData(row).toInt());
    });
    connect(m_albedo, &ColorButton::colorChanged, this,
        [edit](const glm::vec3& c) { edit(Field::Albedo, [&](render::Material& m) { m.albedo = c; }); });
    connect(m_specular, &ColorButton::colorChanged, this,
        [edit](const glm::vec3& c) { edit(Field::Specular, [&](render::Material& m) { m.specular = c; }); });
    connect(m_shininess, &QDoubleSpinBox::valueChanged, this,
        [edit](double v) { edit(Field::Shininess, [&](render::Material& m) { m.shininess = float(v); }); });
    connect(m_emissionColor, &ColorButton::colorChanged, this, [this, edit] {
        edit(Field::EmissionColor, [&](render::Material& m) { m.emission = uiEmission(); });
    });
    connect(m_strength, &QDoubleSpinBox::valueChanged, this, [this, edit] {
        edit(Field::EmissionStrength, [&](render::Material& m) { m.emission = uiEmission(); });
    });
    connect(m_doubleSided, &QCheckBox::toggled, this,
        [edit](bool on) { edit(Field::DoubleSided, [&](render::Material& m) { m.doubleSided = on; }); });
    connect(m_emissive, &QCheckBox::toggled, this, [this, edit](bool on) {
        m_emissionColor->setEnabled(on);
        m_strength->setEnabled(on);
        if (on) {
            // Zero strength would store zero emission, and the switch would read as off again on reload.
            if (m_strength->value() <= 0.0)
                setSpinValue(m_strength, 1.0);
            if (maxComponent(m_emissionColor->color()) <= 0.0f)
                m_emissionColor->setColor(glm::vec3(1.0f));
        } else {
            m_emissionMemory[m_material] = { m_emissionColor->color(), m_strength->value() };
        }
        edit(Field::Emissive, [&](render::Material& m) { m.emission = uiEmission(); });
    });
    // Enter, leaving a box or closing a colour dialog ends the gesture: the next edit of the same field is
    // an undo step of its own.
    const auto endGesture = [this] {
        if (m_document)
            m_document->endEditGesture();
    };
    for (QDoubleSpinBox* spin : { m_shininess, m_strength })
        connect(spin, &QDoubleSpinBox::editingFinished, this, endGesture);
    for (ColorButton* button : { m_albedo, m_specular, m_emissionColor })
        connect(button, &ColorButton::editingFinished, this, endGesture);

    setDocument(nullptr);
}

void MaterialDock::setDocument(doc::Document* document)
{
    disconnect(m_changedConnection);
    disconnect(m_selectionConnection);
    m_document = document;
    m_emissionMemory.clear();
    m_shownMaterial = -1;
    if (m_document) {
        m_changedConnection
            = connect(m_document, &doc::Document::changed, this, &MaterialDock::onDocumentChanged);
        m_selectionConnection
            = connect(m_document, &doc::Document::selectionChanged, this, &MaterialDock::onSelectionChanged);
    }
    rebuildCombo();
    m_material = -1;
    if (m_document && !m_document->state().materials.empty())
        m_material = 0;
    onSelectionChanged(m_document ? m_document->selectedNode() : -1);
    setCurrentMaterial(m_material);
}

void MaterialDock::setCurrentMaterial(int index)
{
    const int count = m_document ? int(m_document->state().materials.size()) : 0;
    m_material = index >= 0 && index < count ? index : -1;
    {
        const QSignalBlocker block(m_combo);
        m_combo->setCurrentIndex(m_combo->findData(m_material));
    }
    loadMaterial();
    updateUsage();
}

void MaterialDock::onSelectionChanged(int node)
{
    // Nothing selected: keep showing the last material, as Blender's properties editor does when pinned.
    if (!m_document || node < 0 || node >= int(m_document->state().nodes.size()))
        return;
    setCurrentMaterial(m_document->state().nodes[std::size_t(node)].material);
}

void MaterialDock::onDocumentChanged(const doc::ChangeEvent& event)
{
    using Kind = doc::ChangeEvent::Kind;
    switch (event.kind) {
    case Kind::Reset:
        m_emissionMemory.clear();
        m_shownMaterial = -1;
        rebuildCombo();
        setCurrentMaterial(m_document->state().materials.empty() ? -1 : 0);
        onSelectionChanged(m_document->selectedNode());
        break;
    case Kind::Material:
        if (!m_applying && (event.index == m_material || event.index < 0))
            loadMaterial();
        break;
    case Kind::Structure:
    case Kind::NodeProperty:
        // Importing or deleting can change the material list; names and counts of users change anyway.
        if (m_combo->count() != int(m_document->state().materials.size()))
            rebuildCombo();
        setCurrentMaterial(m_material);
        break;
    default:
        break;
    }
}

void MaterialDock::rebuildCombo()
{
    const QSignalBlocker block(m_combo);
    m_combo->clear();
    if (!m_document)
        return;
    const auto& materials = m_document->state().materials;
    for (std::size_t i = 0; i < materials.size(); ++i) {
        const QString name = QString::fromStdString(materials[i].name);
        m_combo->addItem(name.isEmpty() ? tr("Material %1").arg(i) : name, int(i));
    }
    m_combo->setCurrentIndex(m_combo->findData(m_material));
}

void MaterialDock::loadMaterial()
{
    const bool valid
        = m_document && m_material >= 0 && m_material < int(m_document->state().materials.size());
    for (QWidget* w : std::initializer_list<QWidget*> { m_albedo, m_texture, m_emissive, m_emissionColor,
             m_strength, m_specular, m_shininess, m_doubleSided })
        w->setEnabled(valid);
    if (!valid) {
        m_texture->setText(tr("—"));
        m_warning->hide();
        return;
    }
    const render::Material& m = m_document->state().materials[std::size_t(m_material)];

    const QSignalBlocker b1(m_albedo), b2(m_emissive), b3(m_emissionColor), b4(m_specular), b5(m_shininess),
        b6(m_doubleSided);
    m_doubleSided->setChecked(m.doubleSided);
    m_albedo->setColor(m.albedo);
    m_texture->setText(m.albedoTexture >= 0 ? tr("texture #%1 × albedo").arg(m.albedoTexture) : tr("none"));
    m_specular->setColor(m.specular);
    setSpinValue(m_shininess, double(m.shininess));

    const bool emissive = m.isEmissive();
    m_emissive->setChecked(emissive);
    if (emissive) {
        // Another material splits so that the brightest channel of the colour is 1. The same one keeps the
        // user's split when it still multiplies out to the stored value, else keeps the colour or the
        // strength when the other alone explains it, so that undoing one shows the other as it was.
        const glm::vec3 color = m_emissionColor->color();
        const float strength = float(m_strength->value());
        if (m_shownMaterial != m_material) {
            const float brightest = maxComponent(m.emission);
            m_emissionColor->setColor(m.emission / brightest);
            setSpinValue(m_strength, double(brightest));
        } else if (!nearlyEqual(color * strength, m.emission)) {
            const float colorMax = maxComponent(color);
            const float strengthForColor = colorMax > 0.0f ? maxComponent(m.emission) / colorMax : 0.0f;
            const glm::vec3 colorForStrength = strength > 0.0f ? m.emission / strength : glm::vec3(-1.0f);
            if (strengthForColor > 0.0f && nearlyEqual(color * strengthForColor, m.emission)) {
                setSpinValue(m_strength, double(strengthForColor));
            } else if (maxComponent(colorForStrength) <= 1.0f && colorForStrength.x >= 0.0f
                && colorForStrength.y >= 0.0f && colorForStrength.z >= 0.0f) {
                m_emissionColor->setColor(colorForStrength);
            } else {
                const float brightest = maxComponent(m.emission);
                m_emissionColor->setColor(m.emission / brightest);
                setSpinValue(m_strength, double(brightest));
            }
        }
    } else {
        const auto it = m_emissionMemory.find(m_material);
        const EmissionMemory memory = it != m_emissionMemory.end() ? it->second : EmissionMemory {};
        m_emissionColor->setColor(memory.color);
        setSpinValue(m_strength, memory.strength);
    }
    m_emissionColor->setEnabled(emissive);
    m_strength->setEnabled(emissive);
    m_shownMaterial = m_material;
    updateWarning();
}

void MaterialDock::updateUsage()
{
    if (!m_document || m_material < 0) {
        m_usage->clear();
        m_usage->setToolTip(QString());
        return;
    }
    QStringList users;
    for (const doc::SceneNode& node : m_document->state().nodes)
        if (node.material == m_material)
            users << node.name;
    if (users.isEmpty()) {
        m_usage->setText(tr("Not used by any node"));
    } else {
        const QString shown = users.size() <= 3
            ? users.join(QStringLiteral(", "))
            : users.mid(0, 3).join(QStringLiteral(", ")) + QStringLiteral(", …");
        m_usage->setText(users.size() == 1 ? tr("Used by 1 node: %1").arg(shown)
                                           : tr("Shared by %1 nodes: %2").arg(users.size()).arg(shown));
    }
    m_usage->setToolTip(users.join(QLatin1Char('\n')));
}

void MaterialDock::updateWarning()
{
    if (!m_document || m_material < 0 || m_material >= int(m_document->state().materials.size())) {
        m_warning->hide();
        return;
    }
    const render::Material& m = m_document->state().materials[std::size_t(m_material)];
    m_warning->setVisible(maxComponent(m.albedo + m.specular) > 1.0f + 1e-4f);
}

glm::vec3 MaterialDock::uiEmission() const
{
    return m_emissive->isChecked() ? m_emissionColor->color() * float(m_strength->value()) : glm::vec3(0.0f);
}

} // namespace vct::ui
