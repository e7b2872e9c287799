#include "EditorTestSetup.h"
#include "TestSupport.h"

#include "ui/LightDock.h"
#include "ui/MainWindow.h"
#include "ui/ViewportWidget.h"

#include "document/Document.h"

#include <QPushButton>
#include <QSettings>
#include <QtTest>

using namespace vct;

/** Panels keep their size when their content changes: the view does not jump. */
class LayoutTest : public QObject {
    Q_OBJECT

public:
    static void initMain() { test::prepareEditorApplication(); }

private slots:
    void addingLightsKeepsTheViewInPlace();
    void restoredSessionKeepsTheViewInPlace();
};

namespace {

QRect viewRect(ui::MainWindow& window)
{
    return QRect(window.viewport()->mapTo(&window, QPoint(0, 0)), window.viewport()->size());
}

QString describe(const QRect& r)
{
    return QStringLiteral("%1,%2 %3x%4").arg(r.x()).arg(r.y()).arg(r.width()).arg(r.height());
}

} // namespace

void LayoutTest::addingLightsKeepsTheViewInPlace()
{
    auto window = test::showEditor(QStringLiteral("builtin:cornell_point"));
    QVERIFY(window);
    QTest::qWait(100);
    const auto viewRect = [&] {
        return QRect(window->viewport()->mapTo(window.get(), QPoint(0, 0)), window->viewport()->size());
    };
    const QRect before = viewRect();
    for (const char* button :
        { "addDirectionalLightButton", "addRectLightButton", "addDiskLightButton", "addPointLightButton" }) {
        auto* add = window->lightDock()->findChild<QPushButton*>(QString::fromLatin1(button));
        QVERIFY2(add, button);
        QTest::mouseClick(add, Qt::LeftButton);
        QTest::qWait(50);
        QVERIFY2(viewRect() == before,
            qPrintable(QStringLiteral("after %1: the view moved from %2,%3 %4x%5 to %6,%7 %8x%9")
                           .arg(QLatin1String(button))
                           .arg(before.x())
                           .arg(before.y())
                           .arg(before.width())
                           .arg(before.height())
                           .arg(viewRect().x())
                           .arg(viewRect().y())
                           .arg(viewRect().width())
                           .arg(viewRect().height())));
    }
}

// Closing saves the window and its docks; the next start restores them where they were (issue 20: a restored
// session opened shifted by about 20 pixels).
void LayoutTest::restoredSessionKeepsTheViewInPlace()
{
    QSettings().remove(QStringLiteral("window"));
    QRect firstView, firstFrame;
    {
        auto window = test::showEditor(QStringLiteral("builtin:cornell_point"));
        QVERIFY(window);
        QTest::qWait(100);
        firstView = viewRect(*window);
        firstFrame = window->geometry();
        QVERIFY(window->close());
    }
    auto window = std::make_unique<ui::MainWindow>();
    window->openInitial(QStringLiteral("builtin:cornell_point"));
    window->show();
    QVERIFY(QTest::qWaitForWindowExposed(window.get()));
    QTest::qWait(100);
    QVERIFY2(window->geometry() == firstFrame,
        qPrintable(
            QStringLiteral("window %1, was %2").arg(describe(window->geometry()), describe(firstFrame))));
    QVERIFY2(viewRect(*window) == firstView,
        qPrintable(QStringLiteral("view %1, was %2").arg(describe(viewRect(*window)), describe(firstView))));
}

QTEST_MAIN(LayoutTest)
#include "tst_Layout.moc"
