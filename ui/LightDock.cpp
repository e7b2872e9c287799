#include "LightDock.h"

#include "ColorButton.h"
#include "SceneTreeModel.h"

#include "document/Document.h"
#include "document/NewLight.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListView>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>
#include <initializer_list>

namespace vct::ui {

namespace {

QString intensityUnit(doc::LightType type)
{
    switch (type) {
    case doc::LightType::Directional:
        return QStringLiteral(" W/m²");
    case doc::LightType::Rect:
    case doc::LightType::Disk:
        return QStringLiteral(" W/(m² sr)");
    case doc::LightType::Point:
    case doc::LightType::Spot:
        break;
    }
    return QStringLiteral(" W/sr");
}

QString directionTip(doc::LightType type)
{
    switch (type) {
    case doc::LightType::Spot:
        return LightDock::tr("The spot's axis (need not be unit length; zero is not allowed)");
    case doc::LightType::Rect:
    case doc::LightType::Disk:
        return LightDock::tr(
            "The way the front face looks; only the front emits (need not be unit length; zero "
            "is not allowed)");
    case doc::LightType::Point:
    case doc::LightType::Directional:
        break;
    }
    return LightDock::tr("The way the light travels (need not be unit length; zero is not allowed)");
}

/** A length in metres, more than zero: a surface light without area emits nothing. */
QDoubleSpinBox* makeLengthSpin(const QString& objectName, const QString& tip)
{
    auto* spin = new QDoubleSpinBox;
    spin->setObjectName(objectName);
    spin->setRange(0.001, 1.0e3);
    spin->setDecimals(3);
    spin->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
    spin->setSuffix(QStringLiteral(" m"));
    spin->setToolTip(tip);
    return spin;
}

void setSpinValue(QDoubleSpinBox* spin, double value)
{
    if (std::abs(spin->value() - value) > 1e-9) {
        const QSignalBlocker block(spin);
        spin->setValue(value);
    }
}

/** Three compact spin boxes labelled X, Y, Z, named `name` and the axis. */
QWidget* makeVectorRow(std::array<QDoubleSpinBox*, 3>& spins, const QString& name, double min, double max,
    const QString& suffix, const QString& tip)
{
    auto* row = new QWidget;
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    const char* axes[] = { "X", "Y", "Z" };
    for (int i = 0; i < 3; ++i) {
        auto* spin = new QDoubleSpinBox;
        spin->setObjectName(name + QLatin1String(axes[i]));
        spin->setRange(min, max);
        spin->setDecimals(3);
        spin->setSingleStep(0.05);
        spin->setSuffix(suffix);
        spin->setPrefix(QStringLiteral("%1 ").arg(QLatin1String(axes[i])));
        spin->setToolTip(tip);
        spin->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        spin->setButtonSymbols(QAbstractSpinBox::NoButtons);
        spins[std::size_t(i)] = spin;
        layout->addWidget(spin);
    }
    return row;
}

} // namespace

LightDock::LightDock(QWidget* parent)
    : QDockWidget(tr("Light"), parent)
{
    setObjectName(QStringLiteral("LightDock"));
    auto* body = new QWidget(this);

    m_model = new SceneTreeModel(this);
    m_list = new QListView;
    m_list->setObjectName(QStringLiteral("lightList"));
    m_list->setModel(m_model);
    m_list->setSelectionMode(QAbstractItemView::SingleSelection);
    m_list->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_list->setMaximumHeight(120);

    m_addPoint = new QPushButton(tr("Add point"));
    m_addPoint->setObjectName(QStringLiteral("addPointLightButton"));
    m_addPoint->setToolTip(tr("Add a point light at the camera's look-at point (one undo step)"));
    m_addDirectional = new QPushButton(tr("Add directional"));
    m_addDirectional->setObjectName(QStringLiteral("addDirectionalLightButton"));
    m_addDirectional->setToolTip(tr("Add a directional (sun) light shining down (one undo step)"));
    m_remove = new QPushButton(tr("Remove"));
    m_remove->setObjectName(QStringLiteral("removeLightButton"));
    m_remove->setToolTip(tr("Remove the selected light (one undo step)"));
    m_addRect = new QPushButton(tr("Add rect"));
    m_addRect->setObjectName(QStringLiteral("addRectLightButton"));
    m_addRect->setToolTip(
        tr("Add a rectangular area light under the scene's top, facing down (one undo step)"));
    m_addDisk = new QPushButton(tr("Add disk"));
    m_addDisk->setObjectName(QStringLiteral("addDiskLightButton"));
    m_addDisk->setToolTip(tr("Add a disk area light under the scene's top, facing down (one undo step)"));
    auto* buttons = new QHBoxLayout;
    buttons->setContentsMargins(0, 0, 0, 0);
    buttons->addWidget(m_addPoint);
    buttons->addWidget(m_addDirectional);
    buttons->addWidget(m_remove);
    // A second row: five buttons in one would widen the dock.
    auto* areaButtons = new QHBoxLayout;
    areaButtons->setContentsMargins(0, 0, 0, 0);
    areaButtons->addWidget(m_addRect);
    areaButtons->addWidget(m_addDisk);
    areaButtons->addStretch();

    m_name = new QLineEdit;
    m_name->setObjectName(QStringLiteral("lightName"));
    m_type = new QComboBox;
    m_type->setObjectName(QStringLiteral("lightType"));
    m_type->addItem(tr("Point"), int(doc::LightType::Point));
    m_type->addItem(tr("Directional"), int(doc::LightType::Directional));
    m_type->addItem(tr("Spot"), int(doc::LightType::Spot));
    m_type->addItem(tr("Rect"), int(doc::LightType::Rect));
    m_type->addItem(tr("Disk"), int(doc::LightType::Disk));
    m_type->setToolTip(tr(
        "Point: radiates from a position (intensity in W/sr).\n"
        "Directional: parallel rays from infinitely far, like the sun (irradiance in W/m²).\n"
        "Spot: a point light sending its intensity (W/sr, on the axis) into a cone, full within the inner "
        "angle and fading to none at the outer one.\n"
        "Rect, Disk: an area light emitting a radiance (W/(m² sr)) from its front face, with soft shadows; "
        "the camera does not see it."));
    m_spotRow = new QWidget;
    auto* spotLayout = new QHBoxLayout(m_spotRow);
    spotLayout->setContentsMargins(0, 0, 0, 0);
    for (QDoubleSpinBox** spin : { &m_spotInner, &m_spotOuter }) {
        *spin = new QDoubleSpinBox;
        (*spin)->setRange(0.0, 90.0);
        (*spin)->setDecimals(1);
        (*spin)->setSuffix(QStringLiteral("°"));
        spotLayout->addWidget(*spin);
    }
    m_spotInner->setObjectName(QStringLiteral("spotInner"));
    m_spotOuter->setObjectName(QStringLiteral("spotOuter"));
    m_spotInner->setToolTip(tr("Inner angle from the axis: full intensity within it"));
    m_spotOuter->setToolTip(tr("Outer angle from the axis: no light beyond it (at most 90°)"));
    m_radius = makeLengthSpin(QStringLiteral("lightRadius"),
        tr("Size of the light: a sphere of this radius softens its shadows; 0 is a point"));
    m_radius->setMinimum(0.0);
    m_angularDiameter = new QDoubleSpinBox;
    m_angularDiameter->setObjectName(QStringLiteral("lightAngularDiameter"));
    // The files refuse 90° and more: half the sky is no longer a light from one direction.
    m_angularDiameter->setRange(0.0, 89.0);
    m_angularDiameter->setDecimals(2);
    m_angularDiameter->setSingleStep(0.1);
    m_angularDiameter->setSuffix(QStringLiteral("°"));
    m_angularDiameter->setToolTip(tr("Angular diameter: how wide the light's disk looks, which softens its "
                                     "shadows without changing its irradiance: the "
                                     "sun's is about 0.53°; 0 is a light from a single direction"));
    m_areaWidth = makeLengthSpin(
        QStringLiteral("areaWidth"), tr("Rects: the width in metres; disks: the diameter in metres"));
    m_areaHeight = makeLengthSpin(QStringLiteral("areaHeight"), tr("The rect's height in metres"));
    m_areaRotation = new QDoubleSpinBox;
    m_areaRotation->setObjectName(QStringLiteral("areaRotation"));
    m_areaRotation->setRange(-360.0, 360.0);
    m_areaRotation->setDecimals(1);
    m_areaRotation->setSuffix(QStringLiteral("°"));
    m_areaRotation->setToolTip(
        tr("Turns the rect about its direction; at 0° its width runs along the horizontal axis across the "
           "direction (world X for a light facing straight up or down)"));
    m_positionRow = makeVectorRow(m_position, QStringLiteral("lightPosition"), -1.0e4, 1.0e4,
        QStringLiteral(" m"), tr("Position in metres"));
    m_directionRow = makeVectorRow(m_direction, QStringLiteral("lightDirection"), -1.0e3, 1.0e3, QString(),
        tr("The way the light travels (need not be unit length; zero is not allowed)"));
    m_color = new ColorButton;
    m_color->setObjectName(QStringLiteral("lightColor"));
    m_color->setDialogTitle(tr("Light colour"));
    m_intensity = new QDoubleSpinBox;
    m_intensity->setObjectName(QStringLiteral("lightIntensity"));
    m_intensity->setRange(0.0, 1.0e6);
    m_intensity->setDecimals(3);
    m_intensity->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
    m_intensity->setToolTip(tr("Emitted per channel = colour × intensity: radiant intensity (W/sr) for point "
                               "and spot lights, irradiance on a facing surface (W/m²) for directional "
                               "lights, radiance of the front face (W/(m² sr)) for rect and disk lights"));
    m_shadows = new QCheckBox(tr("Casts shadows"));
    m_shadows->setObjectName(QStringLiteral("lightShadows"));

    m_editors = new QWidget;
    auto* form = new QFormLayout(m_editors);
    form->setContentsMargins(0, 0, 0, 0);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    form->addRow(tr("Name"), m_name);
    form->addRow(tr("Type"), m_type);
    m_positionLabel = new QLabel(tr("Position"));
    form->addRow(m_positionLabel, m_positionRow);
    m_directionLabel = new QLabel(tr("Direction"));
    form->addRow(m_directionLabel, m_directionRow);
    m_spotLabel = new QLabel(tr("Cone"));
    form->addRow(m_spotLabel, m_spotRow);
    m_radiusLabel = new QLabel(tr("Radius"));
    form->addRow(m_radiusLabel, m_radius);
    // A short label: the form's label column sets the dock's width, and the viewport gives way to it.
    m_angularDiameterLabel = new QLabel(tr("Size"));
    m_angularDiameterLabel->setToolTip(m_angularDiameter->toolTip());
    form->addRow(m_angularDiameterLabel, m_angularDiameter);
    m_areaWidthLabel = new QLabel(tr("Width"));
    form->addRow(m_areaWidthLabel, m_areaWidth);
    m_areaHeightLabel = new QLabel(tr("Height"));
    form->addRow(m_areaHeightLabel, m_areaHeight);
    m_areaRotationLabel = new QLabel(tr("Rotation"));
    form->addRow(m_areaRotationLabel, m_areaRotation);
    form->addRow(tr("Colour"), m_color);
    m_intensityLabel = new QLabel(tr("Intensity"));
    form->addRow(m_intensityLabel, m_intensity);
    form->addRow(QString(), m_shadows);

    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_list);
    layout->addLayout(buttons);
    layout->addLayout(areaButtons);
    layout->addWidget(m_editors);
    layout->addStretch();
    setWidget(body);
    // As wide as the widest light needs, whatever light is shown: rows come and go with the type, and a
    // dock following them resized the view beside it (70 px when a sun was selected).
    const std::initializer_list<QWidget*> optionalRows { m_directionLabel, m_directionRow, m_spotLabel,
        m_spotRow, m_radiusLabel, m_radius, m_angularDiameterLabel, m_angularDiameter, m_areaWidthLabel,
        m_areaWidth, m_areaHeightLabel, m_areaHeight, m_areaRotationLabel, m_areaRotation };
    for (QWidget* w : optionalRows)
        w->show();
    m_intensity->setSuffix(intensityUnit(doc::LightType::Rect)); // the longest unit
    body->setMinimumWidth(body->sizeHint().width());

    connect(m_addPoint, &QPushButton::clicked, this, &LightDock::addPointLight);
    connect(m_addDirectional, &QPushButton::clicked, this, &LightDock::addDirectionalLight);
    connect(m_addRect, &QPushButton::clicked, this, &LightDock::addRectLight);
    connect(m_addDisk, &QPushButton::clicked, this, &LightDock::addDiskLight);
    connect(m_remove, &QPushButton::clicked, this, &LightDock::removeCurrentLight);
    connect(m_model, &QAbstractItemModel::modelReset, this, &LightDock::attachList);
    connect(m_list->selectionModel(), &QItemSelectionModel::currentChanged, this, &LightDock::loadLight);

    using Field = doc::LightField;
    connect(m_name, &QLineEdit::editingFinished, this, [this] {
        const QString name = m_name->text().trimmed();
        applyEdit(Field::Name, [&](doc::LightNode& l) { l.name = name; });
        // Committed: a reload (an undo) may show the document's name again.
        m_name->setModified(false);
    });
    connect(m_type, &QComboBox::currentIndexChanged, this, [this](int row) {
        if (row < 0)
            return;
        const auto type = doc::LightType(m_type->itemData(row).toInt());
        applyEdit(Field::Type, [&](doc::LightNode& l) { l.type = type; });
        loadLight(); // The rows shown and the intensity's name and unit follow the type.
    });
    constexpr Field positionFields[] = { Field::PositionX, Field::PositionY, Field::PositionZ };
    constexpr Field directionFields[] = { Field::DirectionX, Field::DirectionY, Field::DirectionZ };
    for (std::size_t i = 0; i < 3; ++i) {
        connect(m_position[i], &QDoubleSpinBox::valueChanged, this,
            [this, i, field = positionFields[i]](
                double v) { applyEdit(field, [&](doc::LightNode& l) { l.position[int(i)] = float(v); }); });
        connect(m_direction[i], &QDoubleSpinBox::valueChanged, this,
            [this, i, field = directionFields[i]](double v) {
                applyEdit(field, [&](doc::LightNode& l) {
                    glm::vec3 d = l.direction;
                    d[int(i)] = float(v);
                    // A zero direction has no meaning; keep the last usable one (the spin box is reloaded).
                    if (d != glm::vec3(0.0f))
                        l.direction = d;
                });
            });
    }
    // Inner never beyond outer: editing one carries the other along, as one edit.
    connect(m_spotInner, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        applyEdit(Field::SpotInner, [&](doc::LightNode& l) {
            l.spotInnerDeg = float(v);
            l.spotOuterDeg = std::max(l.spotOuterDeg, l.spotInnerDeg);
        });
    });
    connect(m_spotOuter, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        applyEdit(Field::SpotOuter, [&](doc::LightNode& l) {
            l.spotOuterDeg = float(v);
            l.spotInnerDeg = std::min(l.spotInnerDeg, l.spotOuterDeg);
        });
    });
    connect(m_radius, &QDoubleSpinBox::valueChanged, this,
        [this](double v) { applyEdit(Field::Radius, [&](doc::LightNode& l) { l.radius = float(v); }); });
    connect(m_angularDiameter, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        applyEdit(Field::AngularDiameter, [&](doc::LightNode& l) { l.angularDiameterDeg = float(v); });
    });
    connect(m_areaWidth, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        applyEdit(Field::AreaWidth, [&](doc::LightNode& l) { l.areaWidth = float(v); });
    });
    connect(m_areaHeight, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        applyEdit(Field::AreaHeight, [&](doc::LightNode& l) { l.areaHeight = float(v); });
    });
    connect(m_areaRotation, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        applyEdit(Field::AreaRotation, [&](doc::LightNode& l) { l.areaRotationDeg = float(v); });
    });
    connect(m_color, &ColorButton::colorChanged, this,
        [this](const glm::vec3& c) { applyEdit(Field::Color, [&](doc::LightNode& l) { l.color = c; }); });
    connect(m_intensity, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        applyEdit(Field::Intensity, [&](doc::LightNode& l) { l.intensity = float(v); });
    });
    connect(m_shadows, &QCheckBox::toggled, this,
        [this](bool on) { applyEdit(Field::Shadows, [&](doc::LightNode& l) { l.castsShadows = on; }); });
    // Enter, leaving a box or closing the colour dialog ends the gesture: the next edit of the same field is
    // an undo step of its own.
    const auto endGesture = [this] {
        if (m_document)
            m_document->endEditGesture();
    };
    for (QDoubleSpinBox* spin : m_editors->findChildren<QDoubleSpinBox*>())
        connect(spin, &QDoubleSpinBox::editingFinished, this, endGesture);
    connect(m_color, &ColorButton::editingFinished, this, endGesture);

    setDocument(nullptr);
}

void LightDock::setDocument(doc::Document* document)
{
    disconnect(m_changedConnection);
    m_document = document;
    m_model->setDocument(document); // Resets the model, which re-attaches the list.
    attachList();
    if (m_document)
        m_changedConnection
            = connect(m_document, &doc::Document::changed, this, &LightDock::onDocumentChanged);
    loadLight();
}

int LightDock::currentLight() const
{
    return SceneTreeModel::lightIndex(m_list->currentIndex());
}

void LightDock::setCurrentLight(int index)
{
    const QModelIndex item = m_model->indexForLight(index);
    if (item.isValid())
        m_list->setCurrentIndex(item);
}

void LightDock::addPointLight()
{
    addLight(doc::LightType::Point);
}

void LightDock::addDirectionalLight()
{
    addLight(doc::LightType::Directional);
}

void LightDock::addRectLight()
{
    addLight(doc::LightType::Rect);
}

void LightDock::addDiskLight()
{
    addLight(doc::LightType::Disk);
}

void LightDock::addLight(doc::LightType type)
{
    if (!m_document)
        return;
    // The name stays empty: the document numbers new lights per type.
    m_document->addLight(doc::NewLight::make(
        type, m_document->sceneBounds(), m_document->state().camera.lookAt, m_document->state().lights));
    setCurrentLight(int(m_document->state().lights.size()) - 1);
}

void LightDock::removeCurrentLight()
{
    const int light = currentLight();
    if (m_document && light >= 0)
        m_document->removeLight(light);
}

void LightDock::onDocumentChanged(const doc::ChangeEvent& event)
{
    using Kind = doc::ChangeEvent::Kind;
    if ((event.kind == Kind::Lights && !m_applying) || event.kind == Kind::Reset)
        loadLight();
}

void LightDock::attachList()
{
    m_list->setRootIndex(m_model->groupIndex(SceneTreeModel::LightsGroup));
    if (!m_list->currentIndex().isValid() && m_model->rowCount(m_list->rootIndex()) > 0)
        m_list->setCurrentIndex(m_model->indexForLight(0));
    loadLight();
}

void LightDock::applyEdit(doc::LightField field, const std::function<void(doc::LightNode&)>& change)
{
    const int index = currentLight();
    if (!m_document || index < 0 || index >= int(m_document->state().lights.size()))
        return;
    const doc::LightNode before = m_document->state().lights[std::size_t(index)];
    doc::LightNode light = before;
    change(light);
    if (light == before) {
        loadLight(); // A rejected edit (zero direction) shows the stored value again.
        return;
    }
    m_applying = true;
    m_document->setLight(index, light, field);
    m_applying = false;
}

void LightDock::loadLight()
{
    const int index = currentLight();
    const bool valid = m_document && index >= 0 && index < int(m_document->state().lights.size());
    m_editors->setEnabled(valid);
    m_remove->setEnabled(valid);
    m_addPoint->setEnabled(m_document);
    m_addDirectional->setEnabled(m_document);
    m_addRect->setEnabled(m_document);
    m_addDisk->setEnabled(m_document);
    if (!valid) {
        // Without a light the fields must not keep showing the last scene's.
        const QSignalBlocker blockName(m_name), blockIntensity(m_intensity), blockColor(m_color);
        m_name->clear();
        m_intensity->setValue(0.0);
        m_intensity->setSuffix(QString());
        m_color->setColor(glm::vec3(0.0f));
        for (QWidget* w :
            std::initializer_list<QWidget*> { m_directionLabel, m_directionRow, m_spotLabel, m_spotRow,
                m_radiusLabel, m_radius, m_angularDiameterLabel, m_angularDiameter, m_areaWidthLabel,
                m_areaWidth, m_areaHeightLabel, m_areaHeight, m_areaRotationLabel, m_areaRotation })
            w->hide();
        return;
    }
    const doc::LightNode& l = m_document->state().lights[std::size_t(index)];
    const bool positioned = l.isPointLike() || l.isSurface();
    const bool spot = l.type == doc::LightType::Spot;
    const bool surface = l.isSurface();
    const bool rect = l.type == doc::LightType::Rect;

    const QSignalBlocker b1(m_name), b2(m_type), b3(m_shadows), b4(m_intensity), b5(m_spotInner),
        b6(m_spotOuter);
    // Not over a name being typed; once committed (or untouched) it shows the document's, focused or not.
    if (!m_name->hasFocus() || !m_name->isModified())
        m_name->setText(l.name);
    m_type->setCurrentIndex(m_type->findData(int(l.type)));
    for (int i = 0; i < 3; ++i) {
        setSpinValue(m_position[std::size_t(i)], double(l.position[i]));
        setSpinValue(m_direction[std::size_t(i)], double(l.direction[i]));
    }
    m_positionLabel->setText(surface ? tr("Centre") : tr("Position"));
    m_positionLabel->setVisible(positioned);
    m_positionRow->setVisible(positioned);
    const bool directed = l.type != doc::LightType::Point;
    m_directionLabel->setVisible(directed);
    m_directionRow->setVisible(directed);
    for (QDoubleSpinBox* spin : m_direction)
        spin->setToolTip(directionTip(l.type));
    m_spotLabel->setVisible(spot);
    m_spotRow->setVisible(spot);
    setSpinValue(m_spotInner, double(l.spotInnerDeg));
    setSpinValue(m_spotOuter, double(l.spotOuterDeg));
    const bool directional = l.type == doc::LightType::Directional;
    m_radiusLabel->setVisible(l.isPointLike());
    m_radius->setVisible(l.isPointLike());
    setSpinValue(m_radius, double(l.radius));
    m_angularDiameterLabel->setVisible(directional);
    m_angularDiameter->setVisible(directional);
    setSpinValue(m_angularDiameter, double(l.angularDiameterDeg));
    m_areaWidthLabel->setText(rect ? tr("Width") : tr("Diameter"));
    m_areaWidthLabel->setVisible(surface);
    m_areaWidth->setVisible(surface);
    m_areaHeightLabel->setVisible(rect);
    m_areaHeight->setVisible(rect);
    m_areaRotationLabel->setVisible(rect);
    m_areaRotation->setVisible(rect);
    setSpinValue(m_areaWidth, double(l.areaWidth));
    setSpinValue(m_areaHeight, double(l.areaHeight));
    setSpinValue(m_areaRotation, double(l.areaRotationDeg));
    m_color->setColor(l.color);
    m_intensityLabel->setText(surface ? tr("Radiance") : tr("Intensity"));
    m_intensity->setSuffix(intensityUnit(l.type));
    setSpinValue(m_intensity, double(l.intensity));
    m_shadows->setChecked(l.castsShadows);
}

} // namespace vct::ui
