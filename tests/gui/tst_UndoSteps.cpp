#include "EditorTestSetup.h"

#include "ui/LightDock.h"
#include "ui/MainWindow.h"
#include "ui/MaterialDock.h"

#include "document/Document.h"

#include <QAction>
#include <QApplication>
#include <QColorDialog>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QPushButton>
#include <QToolButton>
#include <QUndoStack>
#include <QtTest>

using namespace vct;

/**
 * Undo granularity in the real editor window (under Xvfb): each field of the Material and Light panels is its
 * own undo step, Edit > Undo names it, and the window's undo keys undo the document even while a spin box or
 * line edit has focus.
 */
class UndoStepsTest : public QObject {
    Q_OBJECT

public:
    static void initMain() { test::prepareEditorApplication(); }

private slots:
    void initTestCase();
    void cleanupTestCase();
    void init();
    void albedoThenStrengthUndoesOnlyTheStrength();
    void intensityThenXUndoesOnlyX();
    void undoKeysWorkWithFocusInASpinBox();
    void undoKeysCommitATypedNameFirst();
    void redoHasCtrlYAndCtrlShiftZ();

private:
    template <typename T> T* child(QWidget* parent, const char* name) const;
    QAction* action(const char* name) const;
    /** Gives `widget` keyboard focus in the active window, as a click would. */
    void focus(QWidget* widget);
    /** Selects all of a spin box's text and types `text`, as the user replaces a value. */
    void type(QDoubleSpinBox* spin, const QString& text);
    doc::Document* document() const { return m_window->document(); }
    QUndoStack* undoStack() const { return m_window->document()->undoStack(); }
    /** Adds a point light through the Light panel; its index. */
    int addPointLight();

    std::unique_ptr<ui::MainWindow> m_window;
};

template <typename T> T* UndoStepsTest::child(QWidget* parent, const char* name) const
{
    T* widget = parent->findChild<T*>(QString::fromLatin1(name));
    if (!widget)
        qFatal("no child %s", name);
    return widget;
}

QAction* UndoStepsTest::action(const char* name) const
{
    auto* found = m_window->findChild<QAction*>(QString::fromLatin1(name));
    if (!found)
        qFatal("no action %s", name);
    return found;
}

void UndoStepsTest::focus(QWidget* widget)
{
    widget->setFocus(Qt::MouseFocusReason);
    QTRY_VERIFY(widget->hasFocus());
}

void UndoStepsTest::type(QDoubleSpinBox* spin, const QString& text)
{
    focus(spin);
    spin->selectAll();
    QTest::keyClicks(spin, text);
}

int UndoStepsTest::addPointLight()
{
    QTest::mouseClick(child<QPushButton>(m_window->lightDock(), "addPointLightButton"), Qt::LeftButton);
    return m_window->lightDock()->currentLight();
}

void UndoStepsTest::initTestCase()
{
    m_window = test::showEditor(QStringLiteral("builtin:cornell"));
    QVERIFY(m_window);
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    // The Material panel shares its place with the Transform and Render settings tabs.
    m_window->materialDock()->raise();
}

void UndoStepsTest::cleanupTestCase()
{
    m_window.reset();
}

void UndoStepsTest::init()
{
    // Each case starts from the scene as opened, with nothing to undo and the focus nowhere in particular.
    undoStack()->setIndex(0);
    undoStack()->clear();
    if (!m_window->isActiveWindow()) {
        m_window->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    }
    m_window->setFocus();
}

void UndoStepsTest::albedoThenStrengthUndoesOnlyTheStrength()
{
    ui::MaterialDock* dock = m_window->materialDock();
    int node = -1;
    for (std::size_t i = 0; i < document()->state().nodes.size(); ++i)
        if (document()->state().materials[std::size_t(document()->state().nodes[i].material)].name == "light")
            node = int(i);
    QVERIFY(node >= 0);
    document()->setSelectedNode(node);
    const int light = dock->currentMaterial();
    const render::Material before = document()->state().materials[std::size_t(light)];
    QVERIFY(before.isEmissive());
    auto* strength = child<QDoubleSpinBox>(dock, "emissionStrength");
    const double strengthBefore = strength->value();

    // The albedo through its colour dialog: live preview steps, then OK.
    auto* albedoButton = child<QToolButton>(dock, "albedoButton");
    QTest::mouseClick(albedoButton, Qt::LeftButton);
    auto* dialog = albedoButton->findChild<QColorDialog*>();
    QVERIFY(dialog);
    dialog->setCurrentColor(QColor(200, 60, 60));
    dialog->setCurrentColor(QColor(180, 40, 40));
    dialog->accept();
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    const glm::vec3 albedo = document()->state().materials[std::size_t(light)].albedo;
    QVERIFY(albedo != before.albedo);
    QCOMPARE(undoStack()->count(), 1);

    // Then the strength, typed digit by digit and confirmed with Enter.
    type(strength, QStringLiteral("25"));
    QTest::keyClick(strength, Qt::Key_Return);
    QCOMPARE(strength->value(), 25.0);
    QCOMPARE(undoStack()->count(), 2);
    QCOMPARE(action("undoAction")->text(), QStringLiteral("&Undo Emission strength of light"));

    // One undo: the strength as it was, the albedo still the one picked.
    action("undoAction")->trigger();
    const render::Material& m = document()->state().materials[std::size_t(light)];
    QVERIFY(doc::sameMaterial(m, [&] {
        render::Material expected = before;
        expected.albedo = albedo;
        return expected;
    }()));
    QCOMPARE(strength->value(), strengthBefore);
    QCOMPARE(action("undoAction")->text(), QStringLiteral("&Undo Albedo of light"));

    // The second: the material exactly as opened.
    action("undoAction")->trigger();
    QVERIFY(doc::sameMaterial(document()->state().materials[std::size_t(light)], before));
    QVERIFY(!document()->isModified());
}

void UndoStepsTest::intensityThenXUndoesOnlyX()
{
    ui::LightDock* dock = m_window->lightDock();
    const int light = addPointLight();
    QVERIFY(light >= 0);
    const doc::LightNode added = document()->state().lights[std::size_t(light)];
    const int steps = undoStack()->count();
    auto* intensity = child<QDoubleSpinBox>(dock, "lightIntensity");
    auto* x = child<QDoubleSpinBox>(dock, "lightPositionX");

    type(intensity, QStringLiteral("12"));
    // Moving on to X by clicking it, as the user would: the intensity's gesture ends with its focus.
    type(x, QStringLiteral("0.25"));
    const auto current = [&] { return document()->state().lights[std::size_t(light)]; };
    QCOMPARE(current().intensity, 12.0f);
    QCOMPARE(current().position.x, 0.25f);
    QCOMPARE(undoStack()->count(), steps + 2);
    QCOMPARE(action("undoAction")->text(), QStringLiteral("&Undo Light position X of %1").arg(added.name));

    action("undoAction")->trigger();
    doc::LightNode expected = added;
    expected.intensity = 12.0f;
    QVERIFY(current() == expected);
    QCOMPARE(x->value(), double(added.position.x));
    QCOMPARE(intensity->value(), 12.0);
    QCOMPARE(action("undoAction")->text(), QStringLiteral("&Undo Light intensity of %1").arg(added.name));

    action("undoAction")->trigger();
    QVERIFY(current() == added);
    // The box shows three decimals of the float the document holds.
    QVERIFY(std::abs(intensity->value() - double(added.intensity)) < 1e-3);
}

void UndoStepsTest::undoKeysWorkWithFocusInASpinBox()
{
    ui::LightDock* dock = m_window->lightDock();
    const int light = addPointLight();
    const float before = document()->state().lights[std::size_t(light)].intensity;
    auto* intensity = child<QDoubleSpinBox>(dock, "lightIntensity");
    const auto current = [&] { return document()->state().lights[std::size_t(light)].intensity; };

    type(intensity, QStringLiteral("7"));
    QCOMPARE(current(), 7.0f);
    QVERIFY(intensity->hasFocus());

    // Ctrl+Z in the spin box undoes the document's edit, not the box's text, and the box keeps the focus.
    QTest::keyClick(intensity, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(current(), before);
    QVERIFY(std::abs(intensity->value() - double(before)) < 1e-3);
    QVERIFY(intensity->hasFocus());

    // Ctrl+Y redoes it, as Ctrl+Shift+Z does.
    QTest::keyClick(intensity, Qt::Key_Y, Qt::ControlModifier);
    QCOMPARE(current(), 7.0f);
    QCOMPARE(intensity->value(), 7.0);
    QTest::keyClick(intensity, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(current(), before);
    QTest::keyClick(intensity, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(current(), 7.0f);

    // Typing on after the redo is a step of its own: the next undo goes back to 7, not to before it.
    const int steps = undoStack()->index();
    intensity->selectAll();
    QTest::keyClicks(intensity, QStringLiteral("9"));
    QCOMPARE(current(), 9.0f);
    QCOMPARE(undoStack()->index(), steps + 1);
    QTest::keyClick(intensity, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(current(), 7.0f);
    QCOMPARE(intensity->value(), 7.0);
}

void UndoStepsTest::undoKeysCommitATypedNameFirst()
{
    ui::LightDock* dock = m_window->lightDock();
    const int light = addPointLight();
    const QString before = document()->state().lights[std::size_t(light)].name;
    auto* name = child<QLineEdit>(dock, "lightName");
    const int steps = undoStack()->index();

    focus(name);
    name->selectAll();
    QTest::keyClicks(name, QStringLiteral("Key light"));
    QCOMPARE(document()->state().lights[std::size_t(light)].name, before); // not applied while typing

    // Ctrl+Z applies the typed name (a step) and undoes it: the name as it was, in the document and the box.
    QTest::keyClick(name, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(document()->state().lights[std::size_t(light)].name, before);
    QCOMPARE(name->text(), before);
    QCOMPARE(undoStack()->index(), steps);
    QCOMPARE(undoStack()->count(), steps + 1);
    QCOMPARE(undoStack()->text(steps), QStringLiteral("Rename light %1").arg(before));

    QTest::keyClick(name, Qt::Key_Y, Qt::ControlModifier);
    QCOMPARE(document()->state().lights[std::size_t(light)].name, QStringLiteral("Key light"));
    QCOMPARE(name->text(), QStringLiteral("Key light"));
}

void UndoStepsTest::redoHasCtrlYAndCtrlShiftZ()
{
    const QList<QKeySequence> redo = action("redoAction")->shortcuts();
    QVERIFY(redo.contains(QKeySequence(Qt::CTRL | Qt::Key_Y)));
    QVERIFY(redo.contains(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)));
    QVERIFY(action("undoAction")->shortcuts().contains(QKeySequence(Qt::CTRL | Qt::Key_Z)));

    // From the window itself, not a field, the same keys go through the actions' shortcuts.
    const int light = addPointLight();
    document()->setLight(
        light,
        [&] {
            doc::LightNode l = document()->state().lights[std::size_t(light)];
            l.intensity = 4.0f;
            return l;
        }(),
        doc::LightField::Intensity);
    m_window->setFocus();
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(document()->state().lights[std::size_t(light)].intensity != 4.0f);
    QTest::keyClick(m_window.get(), Qt::Key_Y, Qt::ControlModifier);
    QCOMPARE(document()->state().lights[std::size_t(light)].intensity, 4.0f);
}

QTEST_MAIN(UndoStepsTest)
#include "tst_UndoSteps.moc"
