#include "EditorTestSetup.h"
#include "TestSupport.h"

#include "ui/AboutDialog.h"
#include "ui/MainWindow.h"
#include "ui/RenderSettingsDock.h"
#include "ui/ShortcutsDialog.h"

#include "document/Document.h"
#include "document/DocumentState.h"

#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QSpinBox>
#include <QStatusBar>
#include <QTableWidget>
#include <QTextBrowser>
#include <QUndoStack>
#include <QtTest>

using namespace vct;

namespace {

/** validate()'s figure for a grid, as the editor writes it: GiB to one decimal. */
QString gibibytes(std::uint64_t bytes)
{
    return QString::number(double(bytes) / double(std::uint64_t(1) << 30), 'f', 1) + QStringLiteral(" GiB");
}

} // namespace

/**
 * Issue 20's papercuts in the real main window on builtin:cornell_point: refused settings say why where the
 * eye is, the voxel budget is a control, and Help has About and the keyboard shortcuts. The window is never
 * shown: nothing here needs a frame, and a 512³ grid accepted under a raised budget must not be voxelized on
 * llvmpipe.
 */
class PapercutsTest : public QObject {
    Q_OBJECT

public:
    static void initMain() { test::prepareEditorApplication(); }

private slots:
    void initTestCase();
    void cleanupTestCase();
    void refusedGridSaysWhyInStatusBarAndTooltip();
    void budgetSpinBoxEditsTheSettings();
    void budgetTooSmallForTheGridIsRefused();
    void aboutDialogOpensWithoutBlocking();
    void shortcutsDialogListsEveryActionShortcut();

private:
    template <typename T> T* child(const char* name) const
    {
        return m_window->findChild<T*>(QString::fromLatin1(name));
    }
    const render::RenderSettings& settings() const { return m_window->document()->state().settings; }

    std::unique_ptr<ui::MainWindow> m_window;
};

void PapercutsTest::initTestCase()
{
    m_window = std::make_unique<ui::MainWindow>();
    m_window->openInitial(QStringLiteral("builtin:cornell_point"));
    QCOMPARE(settings().voxelResolution, 128);
    QCOMPARE(settings().voxelBudgetMiB, 4096);
}

void PapercutsTest::cleanupTestCase()
{
    m_window.reset();
}

void PapercutsTest::refusedGridSaysWhyInStatusBarAndTooltip()
{
    auto* combo = child<QComboBox>("voxelResolutionCombo");
    QVERIFY(combo);
    const QString ownTip = combo->toolTip();
    const int undoSteps = m_window->document()->undoStack()->index();

    combo->setCurrentIndex(combo->findData(512));

    // Refused: the grid stays at 128³ in the control and the document, and nothing was pushed.
    QCOMPARE(combo->currentData().toInt(), 128);
    QCOMPARE(settings().voxelResolution, 128);
    QCOMPARE(m_window->document()->undoStack()->index(), undoSteps);
    render::RenderSettings wanted = settings();
    wanted.voxelResolution = 512;
    const QString reason
        = QStringLiteral("512³ needs %1 of voxel textures; the budget is 4.0 GiB (voxel_budget_mb)")
              .arg(gibibytes(wanted.voxelMemoryBytes()));
    const QString status = m_window->statusBar()->currentMessage();
    QVERIFY2(status.startsWith(reason), qPrintable(status));
    QVERIFY2(combo->toolTip().contains(reason), qPrintable(combo->toolTip()));
    QVERIFY2(combo->toolTip().contains(ownTip), "the control's own explanation is kept below the refusal");
    // The dock's own message is at its top now, not under the fold.
    auto* problem = child<QLabel>("settingsProblem");
    QVERIFY(problem && !problem->isHidden());
    QVERIFY(problem->text().startsWith(reason));

    // An accepted edit takes the refusal back.
    combo->setCurrentIndex(combo->findData(64));
    QCOMPARE(settings().voxelResolution, 64);
    QCOMPARE(combo->toolTip(), ownTip);
    QVERIFY(problem->isHidden());
    m_window->document()->undoStack()->undo();
    QCOMPARE(settings().voxelResolution, 128);
    QCOMPARE(combo->currentData().toInt(), 128);
}

void PapercutsTest::budgetSpinBoxEditsTheSettings()
{
    auto* budget = child<QSpinBox>("voxelBudget");
    auto* needed = child<QLabel>("voxelMemoryNeeded");
    auto* combo = child<QComboBox>("voxelResolutionCombo");
    QVERIFY(budget && needed && combo);
    QCOMPARE(budget->value(), 4096);
    // 128³ takes under a GiB: whole MiB, rounded up.
    const std::uint64_t mib = (settings().voxelMemoryBytes() + (1u << 20) - 1) >> 20;
    QCOMPARE(needed->text(), QStringLiteral("needs %1 MiB").arg(mib));
    QUndoStack* undo = m_window->document()->undoStack();
    const int undoSteps = undo->index();

    budget->setValue(32768);
    QCOMPARE(settings().voxelBudgetMiB, 32768);
    QCOMPARE(undo->index(), undoSteps + 1);
    // With the room, 512³ is accepted, and the memory beside the budget follows the grid.
    combo->setCurrentIndex(combo->findData(512));
    QCOMPARE(settings().voxelResolution, 512);
    QVERIFY2(needed->text().contains(gibibytes(settings().voxelMemoryBytes())), qPrintable(needed->text()));

    undo->undo();
    undo->undo();
    QCOMPARE(settings().voxelResolution, 128);
    QCOMPARE(settings().voxelBudgetMiB, 4096);
    QCOMPARE(budget->value(), 4096);
}

void PapercutsTest::budgetTooSmallForTheGridIsRefused()
{
    auto* budget = child<QSpinBox>("voxelBudget");
    QVERIFY(budget);
    QVERIFY(settings().voxelMemoryBytes() > (std::uint64_t(64) << 20));
    budget->setValue(64);
    QCOMPARE(settings().voxelBudgetMiB, 4096);
    QCOMPARE(budget->value(), 4096);
    const QString status = m_window->statusBar()->currentMessage();
    QVERIFY2(status.startsWith(QStringLiteral("A voxel budget of 64 MiB is too small: the 128³ grid needs")),
        qPrintable(status));
    QVERIFY2(budget->toolTip().contains(status), qPrintable(budget->toolTip()));
}

void PapercutsTest::aboutDialogOpensWithoutBlocking()
{
    auto* action = child<QAction>("aboutAction");
    QVERIFY(action);
    // VCT_NO_DIALOGS is set: a modal dialog would have to be skipped, so About must not be one.
    action->trigger();
    auto* dialog = m_window->findChild<ui::AboutDialog*>(QStringLiteral("aboutDialog"));
    QVERIFY(dialog);
    QVERIFY(dialog->isVisible());
    QVERIFY(!dialog->isModal());
    action->trigger();
    QCOMPARE(m_window->findChildren<ui::AboutDialog*>().size(), qsizetype(1));

    QCOMPARE(ui::AboutDialog::version(), QStringLiteral("0.1.0")); // CMakeLists.txt's project(VERSION)
    const QString text = dialog->findChild<QTextBrowser*>(QStringLiteral("aboutText"))->toPlainText();
    for (const char* expected :
        { "VCT Studio 0.1.0", "Qt", "LGPLv3", "Assimp", "BSD-3-Clause", "Embree", "Apache-2.0", "GLM", "MIT",
            "OpenEXR", "Mesa", "Stanford Computer Graphics Laboratory", "Crytek Sponza", "not bundled",
            "Frank Meinl", "Marko Dabrovic", "Morgan McGuire", "CC BY 3.0", "README.md", "docs" })
        QVERIFY2(text.contains(QLatin1String(expected)), expected);

    dialog->close();
    QTRY_VERIFY(!m_window->findChild<ui::AboutDialog*>());
}

void PapercutsTest::shortcutsDialogListsEveryActionShortcut()
{
    auto* action = child<QAction>("shortcutsAction");
    QVERIFY(action);
    action->trigger();
    auto* dialog = m_window->findChild<ui::ShortcutsDialog*>(QStringLiteral("shortcutsDialog"));
    QVERIFY(dialog);
    QVERIFY(dialog->isVisible());
    QVERIFY(!dialog->isModal());

    QStringList keys;
    for (int row = 0; row < dialog->table()->rowCount(); ++row)
        keys << dialog->table()->item(row, 0)->text();
    // Every action of the window with a shortcut has its row, whatever menu or panel it is in.
    int withShortcut = 0;
    for (QAction* a : m_window->findChildren<QAction*>()) {
        if (a->shortcut().isEmpty())
            continue;
        ++withShortcut;
        const QString shortcut = a->shortcut().toString(QKeySequence::NativeText);
        QVERIFY2(
            std::any_of(keys.begin(), keys.end(), [&](const QString& k) { return k.contains(shortcut); }),
            qPrintable(shortcut));
    }
    QVERIFY(withShortcut >= 10);
    for (const char* expected : { "Ctrl+S", "Ctrl+I", "F", "Shift+F", "Home", "Alt+Z", "F2", "W / E / R",
             "Right drag", "W / S with the right button held" })
        QVERIFY2(keys.contains(QLatin1String(expected)), expected);
    const auto rows = dialog->table()->findItems(QStringLiteral("Frame all"), Qt::MatchExactly);
    QCOMPARE(rows.size(), qsizetype(1));
    QCOMPARE(dialog->table()->item(rows.front()->row(), 2)->text(), QStringLiteral("View menu"));

    dialog->close();
    QTRY_VERIFY(!m_window->findChild<ui::ShortcutsDialog*>());
}

QTEST_MAIN(PapercutsTest)
#include "tst_Papercuts.moc"
