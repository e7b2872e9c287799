#include "TransformDock.h"

#include "MixedSpinBox.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

#include <algorithm>

namespace vct::ui {

namespace {

// A float holds a million metres only to 6 cm: further out, the digits typed here would not survive.
constexpr double kMaxPosition = 1.0e6;
constexpr double kMaxRotationDeg = 36000.0;
// Four decimals show the smallest scale exactly; beyond these a node is a speck or swallows the scene's grid.
constexpr double kMinScale = 1.0e-4;
constexpr double kMaxScale = 1.0e4;

void setSpinValue(QDoubleSpinBox* spin, double value)
{
    // Compared as shown, not as numbers: the document stores floats, so the value read back from an edit is
    // never the double just typed, and setting it would rewrite the text under the cursor.
    if (spin->textFromValue(spin->value()) != spin->textFromValue(value)) {
        const QSignalBlocker block(spin);
        spin->setValue(value);
    }
}

void configureSpin(
    QDoubleSpinBox* spin, const QString& name, double min, double max, int decimals, const QString& tip)
{
    spin->setObjectName(name);
    spin->setRange(min, max);
    spin->setDecimals(decimals);
    spin->setToolTip(tip);
    spin->setKeyboardTracking(true);
    spin->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
}

/**
 * Three spin boxes labelled X, Y, Z, one under another as in Blender's sidebar: side by side, three numbers
 * up to a million metres would widen the dock column and the viewport would give way to it.
 */
void addVectorRows(QFormLayout* form, const QString& label, std::array<QDoubleSpinBox*, 3>& spins,
    const QString& name, double min, double max, int decimals, const QString& suffix, const QString& tip)
{
    const char* axes[] = { "X", "Y", "Z" };
    for (int i = 0; i < 3; ++i) {
        auto* spin = new QDoubleSpinBox;
        configureSpin(spin, name + QLatin1String(axes[i]), min, max, decimals, tip);
        spin->setPrefix(QStringLiteral("%1 ").arg(QLatin1String(axes[i])));
        spin->setSuffix(suffix);
        spins[std::size_t(i)] = spin;
        form->addRow(i == 0 ? label : QString(), spin);
    }
}

/** The common value of the three factors, or a negative number when they differ. */
float uniformValue(const glm::vec3& scale)
{
    const float low = std::min({ scale.x, scale.y, scale.z });
    const float high = std::max({ scale.x, scale.y, scale.z });
    // Factors equal to float precision read as one value: the panel shows four decimals of each anyway.
    return high - low <= 1e-6f * high ? scale.x : -1.0f;
}

} // namespace

TransformDock::TransformDock(QWidget* parent)
    : QDockWidget(tr("Transform"), parent)
{
    setObjectName(QStringLiteral("transformDock"));
    auto* body = new QWidget;

    m_node = new QLabel;
    m_node->setObjectName(QStringLiteral("transformNode"));
    m_node->setWordWrap(true);

    m_editors = new QWidget;
    auto* form = new QFormLayout(m_editors);
    form->setContentsMargins(0, 0, 0, 0);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    const QString placementNote
        = tr("Applied on top of the model's own placement, about the model's origin.");
    addVectorRows(form, tr("Position"), m_position, QStringLiteral("position"), -kMaxPosition, kMaxPosition,
        4, QStringLiteral(" m"), tr("Position in metres. %1").arg(placementNote));
    addVectorRows(form, tr("Rotation"), m_rotation, QStringLiteral("rotation"), -kMaxRotationDeg,
        kMaxRotationDeg, 2, QStringLiteral("°"),
        tr("Rotation in degrees about X, then Y, then Z (XYZ Euler angles). %1").arg(placementNote));
    addVectorRows(form, tr("Scale"), m_scale, QStringLiteral("scale"), kMinScale, kMaxScale, 4, QString(),
        tr("Scale along one axis"));
    for (QDoubleSpinBox* spin : m_position)
        spin->setSingleStep(0.01);
    for (QDoubleSpinBox* spin : m_rotation)
        spin->setSingleStep(1.0);
    for (QDoubleSpinBox* spin : m_scale)
        spin->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);

    // Its minimum, 0, one unit of the last decimal below the smallest scale, is the "mixed" marker.
    m_uniformScale = new MixedSpinBox;
    configureSpin(m_uniformScale, QStringLiteral("uniformScale"), 0.0, kMaxScale, 4,
        tr("Sets the scale along all three axes to this value; reads \"mixed\" while they differ"));
    m_uniformScale->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
    form->addRow(tr("Uniform"), m_uniformScale);

    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_node);
    layout->addWidget(m_editors);
    layout->addStretch();
    // Scrolls rather than demanding its ten rows of height from the panels that share the column.
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(body);
    setWidget(scroll);

    using Field = doc::NodeTransformField;
    constexpr Field positionFields[] = { Field::TranslationX, Field::TranslationY, Field::TranslationZ };
    constexpr Field rotationFields[] = { Field::RotationX, Field::RotationY, Field::RotationZ };
    constexpr Field scaleFields[] = { Field::ScaleX, Field::ScaleY, Field::ScaleZ };
    for (int i = 0; i < 3; ++i) {
        const auto axis = std::size_t(i);
        connect(m_position[axis], &QDoubleSpinBox::valueChanged, this,
            [this, i, field = positionFields[i]](
                double v) { applyEdit(field, [&](doc::NodeTransform& t) { t.translation[i] = float(v); }); });
        connect(m_rotation[axis], &QDoubleSpinBox::valueChanged, this,
            [this, i, field = rotationFields[i]](
                double v) { applyEdit(field, [&](doc::NodeTransform& t) { t.rotationDeg[i] = float(v); }); });
        connect(
            m_scale[axis], &QDoubleSpinBox::valueChanged, this, [this, i, field = scaleFields[i]](double v) {
                applyEdit(field, [&](doc::NodeTransform& t) { t.scale[i] = float(v); });
            });
    }
    connect(m_uniformScale, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        // The "mixed" marker, typed as a first digit, is no scale; editingFinished shows the real one again.
        if (m_uniformScale->isMixed())
            return;
        applyEdit(Field::UniformScale, [&](doc::NodeTransform& t) { t.scale = glm::vec3(float(v)); });
    });
    connect(m_uniformScale, &QDoubleSpinBox::editingFinished, this, &TransformDock::load);
    // Enter or leaving a box ends the gesture: the next edit of the same field is an undo step of its own.
    for (QDoubleSpinBox* spin : m_editors->findChildren<QDoubleSpinBox*>())
        connect(spin, &QDoubleSpinBox::editingFinished, this, [this] {
            if (m_document)
                m_document->endEditGesture();
        });

    setDocument(nullptr);
}

void TransformDock::setDocument(doc::Document* document)
{
    disconnect(m_changedConnection);
    disconnect(m_selectionConnection);
    m_document = document;
    if (m_document) {
        m_changedConnection
            = connect(m_document, &doc::Document::changed, this, &TransformDock::onDocumentChanged);
        m_selectionConnection
            = connect(m_document, &doc::Document::selectionChanged, this, &TransformDock::load);
    }
    load();
}

int TransformDock::currentNode() const
{
    if (!m_document)
        return -1;
    const int node = m_document->selectedNode();
    return node >= 0 && node < int(m_document->state().nodes.size()) ? node : -1;
}

void TransformDock::onDocumentChanged(const doc::ChangeEvent& event)
{
    using Kind = doc::ChangeEvent::Kind;
    switch (event.kind) {
    case Kind::NodeTransform:
    case Kind::NodeProperty:
        if (event.index == currentNode() || event.index < 0)
            load();
        break;
    case Kind::Reset:
    case Kind::Structure:
        load();
        break;
    default:
        break;
    }
}

void TransformDock::load()
{
    const int node = currentNode();
    const bool valid = node >= 0;
    m_editors->setEnabled(valid);
    // Values left from the last node would read as the placement of nothing.
    m_editors->setVisible(valid);
    if (!valid) {
        m_node->setText(tr("No node selected: click one in the viewport or the Scene panel."));
        return;
    }
    const doc::SceneNode& n = m_document->state().nodes[std::size_t(node)];
    m_node->setText(n.name);
    const doc::NodeTransform& t = n.transform;
    for (int i = 0; i < 3; ++i) {
        setSpinValue(m_position[std::size_t(i)], double(t.translation[i]));
        setSpinValue(m_rotation[std::size_t(i)], double(t.rotationDeg[i]));
        setSpinValue(m_scale[std::size_t(i)], double(t.scale[i]));
    }
    const float uniform = uniformValue(t.scale);
    if (uniform > 0.0f)
        setSpinValue(m_uniformScale, double(uniform));
    else
        m_uniformScale->showMixed();
}

void TransformDock::applyEdit(
    doc::NodeTransformField field, const std::function<void(doc::NodeTransform&)>& change)
{
    const int node = currentNode();
    if (node < 0)
        return;
    doc::NodeTransform transform = m_document->state().nodes[std::size_t(node)].transform;
    change(transform);
    // The document announces the edit; load() then updates the fields it also changes (uniform, axes).
    m_document->setNodeTransform(node, transform, field);
}

} // namespace vct::ui
