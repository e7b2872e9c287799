#include "EditorTestSetup.h"
#include "TestSupport.h"

#include "ui/LightDock.h"
#include "ui/MainWindow.h"
#include "ui/ViewportWidget.h"

#include "document/Document.h"

#include <QPushButton>
#include <QtTest>

using namespace vct;

/** Panels keep their size when their content changes: the view does not jump. */
class LayoutTest : public QObject {
    Q_OBJECT

public:
    static void initMain() { test::prepareEditorApplication(); }

private slots:
    void addingLightsKeepsTheViewInPlace();
};

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

QTEST_MAIN(LayoutTest)
#include "tst_Layout.moc"
