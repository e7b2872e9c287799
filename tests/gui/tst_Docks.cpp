#include "TestSupport.h"

#include "ui/LightDock.h"
#include "ui/MaterialDock.h"
#include "ui/RenderSettingsDock.h"
#include "ui/SceneGraphDock.h"
#include "ui/SceneTreeModel.h"
#include "ui/StatsDock.h"

#include "core/FrameStats.h"
#include "document/Document.h"

#include <QAbstractItemModelTester>
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QTest>
#include <QTreeView>

#include <memory>

using namespace vct;

namespace {

std::unique_ptr<doc::Document> openCornell()
{
    auto document = std::make_unique<doc::Document>();
    QString error;
    if (!document->newFromScene(QStringLiteral("builtin:cornell"), &error))
        qFatal("cannot open builtin:cornell: %s", qPrintable(error));
    return document;
}

int nodeWithMaterial(const doc::Document& document, const std::string& material)
{
    const auto& state = document.state();
    for (std::size_t i = 0; i < state.nodes.size(); ++i)
        if (state.materials[std::size_t(state.nodes[i].material)].name == material)
            return int(i);
    return -1;
}

template <typename T> T* child(QWidget* parent, const char* name)
{
    T* widget = parent->findChild<T*>(QString::fromLatin1(name));
    if (!widget)
        qFatal("no child %s", name);
    return widget;
}

/** Clicks a check box on its indicator (its centre may lie right of the label, outside the hit area). */
void clickCheckBox(QCheckBox* check)
{
    QTest::mouseClick(check, Qt::LeftButton, {}, QPoint(6, check->height() / 2));
}

} // namespace

class TstDocks : public QObject {
    Q_OBJECT

private slots:
    void sceneTreeModelPassesTesterThroughEdits();
    void renameThroughModelIsUndoable();
    void checkStatesEditVisibilityAndDynamic();
    void sceneGraphDockSyncsSelection();
    void sceneGraphDockDeleteAndDuplicate();
    void materialDockEmissiveToggle();
    void materialDockSpinBurstIsOneUndoStep();
    void renderSettingsPresetIsOneUndoStep();
    void renderSettingsResolutionCombo();
    void lightDockAddAndUndo();
    void lightDockRectAndDiskShowTheirSize();
    void lightDockRadiusAndAngularDiameter();
    void statsDockShowsRows();
};

void TstDocks::sceneTreeModelPassesTesterThroughEdits()
{
    auto document = openCornell();
    ui::SceneTreeModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    model.setDocument(document.get());

    const auto nodeRows = [&] { return model.rowCount(model.groupIndex(ui::SceneTreeModel::SceneGroup)); };
    const auto lightRows = [&] { return model.rowCount(model.groupIndex(ui::SceneTreeModel::LightsGroup)); };
    const int nodes = int(document->state().nodes.size());
    QVERIFY(nodes > 0);
    QCOMPARE(model.rowCount(), 3);
    QCOMPARE(nodeRows(), nodes);
    QCOMPARE(lightRows(), int(document->state().lights.size()));
    QCOMPARE(model.data(model.indexForNode(0)).toString(), document->state().nodes[0].name);
    QCOMPARE(ui::SceneTreeModel::nodeIndex(model.indexForNode(2)), 2);
    QCOMPARE(model.indexForNode(2).data(ui::SceneTreeModel::NodeIndexRole).toInt(), 2);
    QCOMPARE(ui::SceneTreeModel::nodeIndex(model.groupIndex(ui::SceneTreeModel::SceneGroup)), -1);

    document->setNodeName(1, QStringLiteral("renamed"));
    document->setNodeVisible(2, false);
    document->setNodeDynamic(3, true);
    document->duplicateNode(0);
    QCOMPARE(nodeRows(), nodes + 1);
    document->deleteNode(1);
    QCOMPARE(nodeRows(), nodes);
    doc::LightNode light;
    light.type = doc::LightType::Directional;
    document->addLight(light);
    QCOMPARE(lightRows(), int(document->state().lights.size()));
    QCOMPARE(ui::SceneTreeModel::lightIndex(model.indexForLight(lightRows() - 1)), lightRows() - 1);
    document->removeLight(0);
    QCOMPARE(lightRows(), int(document->state().lights.size()));

    while (document->undoStack()->canUndo()) {
        document->undoStack()->undo();
        QCOMPARE(nodeRows(), int(document->state().nodes.size()));
        QCOMPARE(lightRows(), int(document->state().lights.size()));
    }
    QCOMPARE(nodeRows(), nodes);
    while (document->undoStack()->canRedo())
        document->undoStack()->redo();
    QCOMPARE(nodeRows(), int(document->state().nodes.size()));

    QString error;
    QVERIFY2(document->newFromScene(QStringLiteral("builtin:cornell_point"), &error), qPrintable(error));
    QCOMPARE(nodeRows(), int(document->state().nodes.size()));
    QCOMPARE(lightRows(), int(document->state().lights.size()));
    QVERIFY(lightRows() > 0);
}

void TstDocks::renameThroughModelIsUndoable()
{
    auto document = openCornell();
    ui::SceneTreeModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    model.setDocument(document.get());

    const QString before = document->state().nodes[0].name;
    QVERIFY(model.setData(model.indexForNode(0), QStringLiteral("Floor 2"), Qt::EditRole));
    QCOMPARE(document->state().nodes[0].name, QStringLiteral("Floor 2"));
    QCOMPARE(model.indexForNode(0).data().toString(), QStringLiteral("Floor 2"));
    QCOMPARE(document->undoStack()->count(), 1);
    document->undoStack()->undo();
    QCOMPARE(document->state().nodes[0].name, before);
    QCOMPARE(model.indexForNode(0).data().toString(), before);
    // An empty name is refused rather than stored.
    QVERIFY(!model.setData(model.indexForNode(0), QStringLiteral("  "), Qt::EditRole));
    QCOMPARE(document->state().nodes[0].name, before);
}

void TstDocks::checkStatesEditVisibilityAndDynamic()
{
    auto document = openCornell();
    ui::SceneTreeModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    model.setDocument(document.get());

    const QModelIndex name = model.indexForNode(1);
    QCOMPARE(name.data(Qt::CheckStateRole).toInt(), int(Qt::Checked));
    QVERIFY(model.flags(name) & Qt::ItemIsUserCheckable);
    QVERIFY(model.setData(name, Qt::Unchecked, Qt::CheckStateRole));
    QVERIFY(!document->state().nodes[1].visible);
    QCOMPARE(model.indexForNode(1).data(Qt::CheckStateRole).toInt(), int(Qt::Unchecked));
    QVERIFY(document->buildRenderScene().meshes.size() < document->state().nodes.size());

    const QModelIndex dynamic = model.indexForNode(1, ui::SceneTreeModel::DynamicColumn);
    QCOMPARE(dynamic.data(Qt::CheckStateRole).toInt(),
        int(document->state().nodes[1].dynamic ? Qt::Checked : Qt::Unchecked));
    QVERIFY(model.setData(dynamic, Qt::Checked, Qt::CheckStateRole));
    QVERIFY(document->state().nodes[1].dynamic);

    document->undoStack()->undo();
    document->undoStack()->undo();
    QVERIFY(document->state().nodes[1].visible);
    QCOMPARE(model.indexForNode(1).data(Qt::CheckStateRole).toInt(), int(Qt::Checked));
}

void TstDocks::sceneGraphDockSyncsSelection()
{
    auto document = openCornell();
    ui::SceneGraphDock dock;
    QCOMPARE(dock.objectName(), QStringLiteral("SceneGraphDock"));
    dock.setDocument(document.get());
    dock.show();

    document->setSelectedNode(2);
    QCOMPARE(ui::SceneTreeModel::nodeIndex(dock.view()->currentIndex()), 2);
    QVERIFY(dock.deleteAction()->isEnabled());

    dock.view()->setCurrentIndex(dock.model()->indexForNode(4));
    QCOMPARE(document->selectedNode(), 4);

    // Selecting a group row is no node.
    dock.view()->setCurrentIndex(dock.model()->groupIndex(ui::SceneTreeModel::LightsGroup));
    QCOMPARE(document->selectedNode(), -1);
    QVERIFY(!dock.deleteAction()->isEnabled());
}

void TstDocks::sceneGraphDockDeleteAndDuplicate()
{
    auto document = openCornell();
    ui::SceneGraphDock dock;
    dock.setDocument(document.get());
    dock.show();
    const int nodes = int(document->state().nodes.size());

    document->setSelectedNode(3);
    dock.duplicateAction()->trigger();
    QCOMPARE(int(document->state().nodes.size()), nodes + 1);
    document->setSelectedNode(0);
    const QString deleted = document->state().nodes[0].name;
    dock.deleteAction()->trigger();
    QCOMPARE(int(document->state().nodes.size()), nodes);
    QVERIFY(document->state().nodes[0].name != deleted);

    document->setSelectedNode(1);
    QCOMPARE(dock.toggleVisibleAction()->text(), QStringLiteral("Hide"));
    dock.toggleVisibleAction()->trigger();
    QVERIFY(!document->state().nodes[1].visible);
    QCOMPARE(dock.toggleVisibleAction()->text(), QStringLiteral("Show"));
    dock.dynamicAction()->trigger();
    QVERIFY(document->state().nodes[1].dynamic);
    QVERIFY(dock.dynamicAction()->isChecked());

    while (document->undoStack()->canUndo())
        document->undoStack()->undo();
    QCOMPARE(int(document->state().nodes.size()), nodes);
    QCOMPARE(document->state().nodes[0].name, deleted);
}

void TstDocks::materialDockEmissiveToggle()
{
    auto document = openCornell();
    ui::MaterialDock dock;
    QCOMPARE(dock.objectName(), QStringLiteral("MaterialDock"));
    dock.setDocument(document.get());
    dock.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dock));

    const int node = nodeWithMaterial(*document, "white");
    QVERIFY(node >= 0);
    document->setSelectedNode(node);
    const int white = document->state().nodes[std::size_t(node)].material;
    QCOMPARE(dock.currentMaterial(), white);
    QCOMPARE(child<QComboBox>(&dock, "materialCombo")->currentText(), QStringLiteral("white"));

    auto* emissive = child<QCheckBox>(&dock, "emissiveCheck");
    auto* strength = child<QDoubleSpinBox>(&dock, "emissionStrength");
    QVERIFY(!emissive->isChecked());
    QVERIFY(!strength->isEnabled());
    QVERIFY(!document->state().materials[std::size_t(white)].isEmissive());

    clickCheckBox(emissive);
    QVERIFY(emissive->isChecked());
    QVERIFY(strength->isEnabled());
    QVERIFY(document->state().materials[std::size_t(white)].isEmissive());
    QCOMPARE(document->undoStack()->count(), 1);

    document->undoStack()->undo();
    QVERIFY(!document->state().materials[std::size_t(white)].isEmissive());
    QVERIFY(!emissive->isChecked());

    // Off keeps the colour and strength in the panel, so on brings them back.
    clickCheckBox(emissive);
    strength->setValue(3.0);
    clickCheckBox(emissive);
    QVERIFY(!document->state().materials[std::size_t(white)].isEmissive());
    QCOMPARE(strength->value(), 3.0);
    clickCheckBox(emissive);
    QCOMPARE(document->state().materials[std::size_t(white)].emission.x, 3.0f);

    // An emissive material from the file splits into colour times strength (brightest channel 1).
    document->setSelectedNode(nodeWithMaterial(*document, "light"));
    QVERIFY(emissive->isChecked());
    QCOMPARE(strength->value(), 17.0);
}

void TstDocks::materialDockSpinBurstIsOneUndoStep()
{
    auto document = openCornell();
    ui::MaterialDock dock;
    dock.setDocument(document.get());
    dock.show();
    const int node = nodeWithMaterial(*document, "white");
    document->setSelectedNode(node);
    const int white = dock.currentMaterial();

    auto* shininess = child<QDoubleSpinBox>(&dock, "shininessSpin");
    shininess->selectAll();
    QTest::keyClicks(shininess, QStringLiteral("250"));
    QTest::keyClick(shininess, Qt::Key_Up);
    QTest::keyClick(shininess, Qt::Key_Up);
    QVERIFY(document->state().materials[std::size_t(white)].shininess > 250.0f);
    QCOMPARE(document->undoStack()->count(), 1);

    document->undoStack()->undo();
    QCOMPARE(document->state().materials[std::size_t(white)].shininess, 0.0f);
    QCOMPARE(shininess->value(), 0.0);
}

void TstDocks::renderSettingsPresetIsOneUndoStep()
{
    auto document = openCornell();
    ui::RenderSettingsDock dock;
    QCOMPARE(dock.objectName(), QStringLiteral("RenderSettingsDock"));
    dock.setDocument(document.get());
    dock.show();
    const render::RenderSettings before = document->state().settings;

    QTest::mouseClick(child<QPushButton>(&dock, "presetHigh"), Qt::LeftButton);
    const render::RenderSettings& s = document->state().settings;
    // The presets of docs/ACCURACY.md: High is Balanced (the defaults) with more, narrower cones.
    QCOMPARE(s.voxelResolution, 128);
    QCOMPARE(s.diffuseConeCount, 13);
    QCOMPARE(s.diffuseApertureDeg, 20.0f);
    QVERIFY(s.anisotropicMips);
    QVERIFY(s.dropBackFaces);
    QCOMPARE(s.bounces, render::RenderSettings::kConvergedBounces);
    QCOMPARE(s.bounceCellSize, 4);
    QCOMPARE(s.higherBounceCellSize, 8);
    QCOMPARE(s.indirectDivisor, 4);
    QCOMPARE(document->undoStack()->count(), 1);
    QVERIFY(child<QPushButton>(&dock, "presetHigh")->isChecked());
    QVERIFY(!child<QPushButton>(&dock, "presetBalanced")->isChecked());
    QCOMPARE(child<QComboBox>(&dock, "bouncesCombo")->currentData().toInt(),
        render::RenderSettings::kConvergedBounces);

    QTest::mouseClick(child<QPushButton>(&dock, "presetFast"), Qt::LeftButton);
    QCOMPARE(document->state().settings.voxelResolution, 64);
    QVERIFY(!document->state().settings.anisotropicMips);
    QCOMPARE(document->state().settings.bounces, 1);
    QCOMPARE(document->state().settings.diffuseConeCount, 5);
    // Box mips have no directions: the back-face box has nothing to act on.
    QVERIFY(!child<QCheckBox>(&dock, "dropBackFacesCheck")->isEnabled());
    QCOMPARE(child<QComboBox>(&dock, "voxelResolutionCombo")->currentData().toInt(), 64);
    QCOMPARE(document->undoStack()->count(), 2);

    document->undoStack()->undo();
    document->undoStack()->undo();
    QCOMPARE(document->state().settings.bounces, before.bounces);
    QCOMPARE(document->state().settings.anisotropicMips, before.anisotropicMips);
    QCOMPARE(child<QComboBox>(&dock, "bouncesCombo")->currentData().toInt(), before.bounces);
    QVERIFY(child<QPushButton>(&dock, "presetBalanced")->isChecked()
        == (before.bounces == render::RenderSettings::kConvergedBounces && before.anisotropicMips));

    // The indirect-resolution combo edits the setting like any other field.
    auto* indirect = child<QComboBox>(&dock, "indirectResolutionCombo");
    indirect->setCurrentIndex(indirect->findData(1));
    QCOMPARE(document->state().settings.indirectDivisor, 1);

    // So does the back-face box, on by default with anisotropic mips.
    auto* backFaces = child<QCheckBox>(&dock, "dropBackFacesCheck");
    QVERIFY(backFaces->isEnabled() && backFaces->isChecked());
    backFaces->click();
    QVERIFY(!document->state().settings.dropBackFaces);
    document->undoStack()->undo();
    QVERIFY(document->state().settings.dropBackFaces);
    QVERIFY(backFaces->isChecked());
}

void TstDocks::renderSettingsResolutionCombo()
{
    auto document = openCornell();
    ui::RenderSettingsDock dock;
    dock.setDocument(document.get());
    dock.show();

    auto* combo = child<QComboBox>(&dock, "voxelResolutionCombo");
    combo->setCurrentIndex(combo->findData(64));
    QCOMPARE(document->state().settings.voxelResolution, 64);
    QTest::keyClick(combo, Qt::Key_Down);
    QCOMPARE(document->state().settings.voxelResolution, 128);

    // One grid or a clipmap's levels, one undoable edit of voxel_mode and clip_levels together.
    auto* grids = child<QComboBox>(&dock, "gridLevelsCombo");
    QCOMPARE(grids->currentData().toInt(), 1);
    const int steps = document->undoStack()->count();
    grids->setCurrentIndex(grids->findData(3));
    QCOMPARE(document->state().settings.voxelMode, render::VoxelMode::Clipmap);
    QCOMPARE(document->state().settings.clipLevels, 3);
    QCOMPARE(document->undoStack()->count(), steps + 1);
    document->undoStack()->undo();
    QCOMPARE(document->state().settings.voxelMode, render::VoxelMode::Dense);
    QCOMPARE(grids->currentData().toInt(), 1);
    grids->setCurrentIndex(grids->findData(0)); // one grid, sparse
    QCOMPARE(document->state().settings.voxelMode, render::VoxelMode::Sparse);
    document->undoStack()->undo();
    QCOMPARE(document->state().settings.voxelMode, render::VoxelMode::Dense);
    QCOMPARE(grids->currentData().toInt(), 1);

    // "auto" (the spin box's minimum) stores a negative distance.
    auto* distance = child<QDoubleSpinBox>(&dock, "maxDistance");
    QCOMPARE(distance->text(), QStringLiteral("auto"));
    distance->setValue(2.5);
    QCOMPARE(document->state().settings.maxDistance, 2.5f);
    distance->setValue(distance->minimum());
    QVERIFY(document->state().settings.maxDistance < 0.0f);

    // The bounce solve's step, one undoable edit, and shown again after an undo.
    auto* bounceStep = child<QDoubleSpinBox>(&dock, "bounceStep");
    QCOMPARE(bounceStep->value(), double(document->state().settings.bounceStepScale));
    const int before = document->undoStack()->count();
    bounceStep->setValue(1.0);
    QCOMPARE(document->state().settings.bounceStepScale, 1.0f);
    QCOMPARE(document->undoStack()->count(), before + 1);
    document->undoStack()->undo();
    QCOMPARE(document->state().settings.bounceStepScale, render::RenderSettings {}.bounceStepScale);
    QCOMPARE(bounceStep->value(), double(render::RenderSettings {}.bounceStepScale));

    auto* view = child<QComboBox>(&dock, "viewCombo");
    view->setCurrentIndex(view->findData(int(render::DebugView::AmbientOcclusion)));
    QCOMPARE(document->state().settings.view, render::DebugView::AmbientOcclusion);
    clickCheckBox(child<QCheckBox>(&dock, "indirectSpecularCheck"));
    QVERIFY(!document->state().settings.indirectSpecular);
}

void TstDocks::lightDockAddAndUndo()
{
    auto document = openCornell();
    ui::LightDock dock;
    QCOMPARE(dock.objectName(), QStringLiteral("LightDock"));
    dock.setDocument(document.get());
    dock.show();
    const int lights = int(document->state().lights.size());

    QTest::mouseClick(child<QPushButton>(&dock, "addPointLightButton"), Qt::LeftButton);
    QCOMPARE(int(document->state().lights.size()), lights + 1);
    QCOMPARE(document->state().lights.back().type, doc::LightType::Point);
    QCOMPARE(dock.currentLight(), lights);
    auto* intensity = child<QDoubleSpinBox>(&dock, "lightIntensity");
    QVERIFY(intensity->suffix().contains(QStringLiteral("W/sr")));
    document->undoStack()->undo();
    QCOMPARE(int(document->state().lights.size()), lights);

    QTest::mouseClick(child<QPushButton>(&dock, "addDirectionalLightButton"), Qt::LeftButton);
    QCOMPARE(document->state().lights.back().type, doc::LightType::Directional);
    QVERIFY(intensity->suffix().contains(QStringLiteral("W/m²")));
    intensity->setValue(5.0);
    QCOMPARE(document->state().lights.back().intensity, 5.0f);
    clickCheckBox(child<QCheckBox>(&dock, "lightShadows"));
    QVERIFY(!document->state().lights.back().castsShadows);

    QTest::mouseClick(child<QPushButton>(&dock, "removeLightButton"), Qt::LeftButton);
    QCOMPARE(int(document->state().lights.size()), lights);
    document->undoStack()->undo();
    QCOMPARE(int(document->state().lights.size()), lights + 1);

    // With no light left, the panel shows none: not the last light's name and values.
    while (!document->state().lights.empty())
        document->removeLight(0);
    QCOMPARE(dock.currentLight(), -1);
    QVERIFY(child<QLineEdit>(&dock, "lightName")->text().isEmpty());
    QCOMPARE(intensity->value(), 0.0);
    QVERIFY(!intensity->isEnabled());
}

void TstDocks::lightDockRectAndDiskShowTheirSize()
{
    auto document = openCornell();
    ui::LightDock dock;
    dock.setDocument(document.get());
    dock.show();
    QTest::mouseClick(child<QPushButton>(&dock, "addPointLightButton"), Qt::LeftButton);
    const int light = dock.currentLight();
    auto* width = child<QDoubleSpinBox>(&dock, "areaWidth");
    auto* height = child<QDoubleSpinBox>(&dock, "areaHeight");
    auto* rotation = child<QDoubleSpinBox>(&dock, "areaRotation");
    auto* intensity = child<QDoubleSpinBox>(&dock, "lightIntensity");
    QVERIFY(!width->isVisible() && !height->isVisible() && !rotation->isVisible());

    auto* type = child<QComboBox>(&dock, "lightType");
    type->setCurrentIndex(type->findData(int(doc::LightType::Rect)));
    QCOMPARE(document->state().lights[std::size_t(light)].type, doc::LightType::Rect);
    QVERIFY(width->isVisible() && height->isVisible() && rotation->isVisible());
    QVERIFY(!child<QDoubleSpinBox>(&dock, "spotInner")->isVisible());
    QVERIFY(intensity->suffix().contains(QStringLiteral("W/(m² sr)")));
    QCOMPARE(width->value(), 1.0);

    // Each field is its own undo step (SetLightCommand::mergeWith): the switch to a rect, the height, the
    // rotation.
    const auto current = [&] { return document->state().lights[std::size_t(light)]; };
    const int steps = document->undoStack()->count();
    height->setValue(0.25);
    QCOMPARE(current().areaHeight, 0.25f);
    rotation->setValue(45.0);
    QCOMPARE(current().areaRotationDeg, 45.0f);
    QCOMPARE(document->undoStack()->count(), steps + 2);
    document->undoStack()->undo();
    QCOMPARE(current().areaRotationDeg, 0.0f);
    QCOMPARE(current().areaHeight, 0.25f);
    QCOMPARE(rotation->value(), 0.0);
    document->undoStack()->undo();
    QCOMPARE(current().areaHeight, 1.0f);
    QCOMPARE(current().type, doc::LightType::Rect);
    document->undoStack()->undo();
    QCOMPARE(current().type, doc::LightType::Point);
    QVERIFY(!width->isVisible() && !height->isVisible() && !rotation->isVisible());
    QVERIFY(intensity->suffix().contains(QStringLiteral("W/sr")));
    for (int i = 0; i < 3; ++i)
        document->undoStack()->redo();
    QVERIFY(height->isVisible());
    QCOMPARE(height->value(), 0.25);
    QCOMPARE(rotation->value(), 45.0);

    // A disk has a diameter only.
    type->setCurrentIndex(type->findData(int(doc::LightType::Disk)));
    QVERIFY(width->isVisible() && !height->isVisible() && !rotation->isVisible());
    width->setValue(0.5);
    QCOMPARE(current().areaWidth, 0.5f);
    QCOMPARE(document->buildRenderScene().surfaceLights.back().width, 0.5f);
    QCOMPARE(document->undoStack()->text(document->undoStack()->index() - 1),
        QStringLiteral("Light diameter of %1").arg(current().name));
    document->undoStack()->undo();
    QCOMPARE(current().areaWidth, 1.0f);
    QCOMPARE(current().type, doc::LightType::Disk);
    document->undoStack()->setIndex(steps - 1);
    QCOMPARE(current().type, doc::LightType::Point);
    QVERIFY(document->buildRenderScene().surfaceLights.empty());

    // Added ones hang under the box's top, facing down, inside it.
    const render::Aabb bounds = document->buildRenderScene().bounds();
    QTest::mouseClick(child<QPushButton>(&dock, "addRectLightButton"), Qt::LeftButton);
    const doc::LightNode rect = document->state().lights.back();
    QCOMPARE(rect.type, doc::LightType::Rect);
    QCOMPARE(rect.name, QStringLiteral("Rect light 1"));
    QCOMPARE(rect.direction, glm::vec3(0.0f, -1.0f, 0.0f));
    QVERIFY(rect.position.y < bounds.max.y && rect.position.y > bounds.min.y);
    QVERIFY(rect.areaWidth > 0.0f && rect.areaWidth <= bounds.size().x);
    QTest::mouseClick(child<QPushButton>(&dock, "addDiskLightButton"), Qt::LeftButton);
    QCOMPARE(document->state().lights.back().type, doc::LightType::Disk);
    QVERIFY(width->isVisible() && !height->isVisible());
    document->undoStack()->undo();
    document->undoStack()->undo();
    QCOMPARE(document->state().lights.back().type, doc::LightType::Point);
}

void TstDocks::lightDockRadiusAndAngularDiameter()
{
    auto document = openCornell();
    ui::LightDock dock;
    dock.setDocument(document.get());
    dock.show();
    const int lights = int(document->state().lights.size());
    auto* radius = child<QDoubleSpinBox>(&dock, "lightRadius");
    auto* diameter = child<QDoubleSpinBox>(&dock, "lightAngularDiameter");

    QTest::mouseClick(child<QPushButton>(&dock, "addPointLightButton"), Qt::LeftButton);
    const int point = dock.currentLight();
    QVERIFY(radius->isVisible() && !diameter->isVisible());
    QCOMPARE(radius->value(), 0.0);
    QVERIFY(radius->toolTip().contains(QStringLiteral("0 is a point")));

    // Its own undo step after the add, and it reaches the renderer's light.
    const int steps = document->undoStack()->count();
    radius->setValue(0.2);
    QCOMPARE(document->state().lights[std::size_t(point)].radius, 0.2f);
    QCOMPARE(document->buildRenderScene().pointLights.back().radius, 0.2f);
    QCOMPARE(document->undoStack()->count(), steps + 1);
    ui::SceneTreeModel model;
    model.setDocument(document.get());
    QVERIFY(
        model.data(model.indexForLight(point), Qt::ToolTipRole).toString().contains(QStringLiteral("0.2 m")));
    document->undoStack()->undo();
    QCOMPARE(int(document->state().lights.size()), lights + 1);
    QCOMPARE(document->state().lights[std::size_t(point)].radius, 0.0f);
    QCOMPARE(radius->value(), 0.0);
    document->undoStack()->redo();
    QCOMPARE(radius->value(), 0.2);

    // A spot keeps the radius; a directional light has an angular diameter instead.
    auto* type = child<QComboBox>(&dock, "lightType");
    type->setCurrentIndex(type->findData(int(doc::LightType::Spot)));
    QVERIFY(radius->isVisible() && !diameter->isVisible());
    QCOMPARE(document->buildRenderScene().pointLights.back().radius, 0.2f);
    QTest::mouseClick(child<QPushButton>(&dock, "addDirectionalLightButton"), Qt::LeftButton);
    const int sun = dock.currentLight();
    QCOMPARE(document->state().lights[std::size_t(sun)].type, doc::LightType::Directional);
    QVERIFY(!radius->isVisible() && diameter->isVisible());
    QVERIFY(diameter->toolTip().contains(QStringLiteral("0.53°")));
    QCOMPARE(diameter->maximum(), 89.0);
    diameter->setValue(0.53);
    QCOMPARE(document->state().lights[std::size_t(sun)].angularDiameterDeg, 0.53f);
    QCOMPARE(document->buildRenderScene().directionalLights.back().angularDiameterDeg, 0.53f);
    document->undoStack()->undo();
    QCOMPARE(document->state().lights[std::size_t(sun)].angularDiameterDeg, 0.0f);
    QCOMPARE(document->state().lights[std::size_t(sun)].type, doc::LightType::Directional);
    QCOMPARE(diameter->value(), 0.0);
}

void TstDocks::statsDockShowsRows()
{
    ui::StatsDock dock;
    QCOMPARE(dock.objectName(), QStringLiteral("StatsDock"));
    render::FrameStats stats;
    stats.passes = { { "voxelize", "run", "scene changed", 1.25 },
        { "mipmap", "reused", "inputs unchanged", 0.0 }, { "cone_trace", "run", "every frame", 2.5 } };
    stats.totalGpuMs = 3.75;
    stats.voxelBytes = 16u * 1024u * 1024u;
    stats.voxelResolution = 128;
    stats.voxelSize = 0.02f;
    stats.width = 640;
    stats.height = 480;
    dock.showStats(stats);

    QTableWidget* table = dock.table();
    QCOMPARE(table->rowCount(), 3);
    QCOMPARE(table->item(0, 0)->text(), QStringLiteral("voxelize"));
    QCOMPARE(table->item(1, 1)->text(), QStringLiteral("reused"));
    QCOMPARE(table->item(1, 2)->text(), QStringLiteral("inputs unchanged"));
    QCOMPARE(table->item(0, 3)->text(), QStringLiteral("1.250"));
    // A dozen passes show without scrolling, and a long reason wraps instead of being cut.
    QVERIFY(table->minimumHeight()
        >= table->horizontalHeader()->sizeHint().height() + 12 * table->fontMetrics().height());
    QVERIFY(table->wordWrap());
    QCOMPARE(child<QLabel>(&dock, "totalGpuLabel")->text(), QStringLiteral("3.750 ms"));
    QCOMPARE(child<QLabel>(&dock, "voxelMemoryLabel")->text(), QStringLiteral("16.0 MiB"));
    QVERIFY(child<QLabel>(&dock, "voxelGridLabel")->text().startsWith(QStringLiteral("128³")));

    stats.passes.resize(1);
    dock.showStats(stats);
    QCOMPARE(table->rowCount(), 1);
}

QTEST_MAIN(TstDocks)
#include "tst_Docks.moc"
