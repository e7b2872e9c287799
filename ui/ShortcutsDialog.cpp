#include "ShortcutsDialog.h"

#include "ViewportWidget.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QHeaderView>
#include <QMenu>
#include <QMenuBar>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <limits>
#include <vector>

namespace vct::ui {

namespace {

struct Row {
    QString keys;
    QString command;
    QString where;
    int rank = 0; // menus in menu-bar order, then panels, then the viewport
};

/** A menu item's text as read: no mnemonic ampersands, no trailing "...". */
QString plainText(QString text)
{
    text.replace(QStringLiteral("&&"), QStringLiteral("\x01"));
    text.remove(QLatin1Char('&'));
    text.replace(QLatin1Char('\x01'), QLatin1Char('&'));
    if (text.endsWith(QStringLiteral("...")))
        text.chop(3);
    return text;
}

/** The menu-bar menu `menu` hangs under (itself when it is one), or null. */
QMenu* topMenu(QMenu* menu)
{
    while (menu && qobject_cast<QMenu*>(menu->parentWidget()))
        menu = qobject_cast<QMenu*>(menu->parentWidget());
    return menu;
}

Row rowFor(QAction* action, const QMenuBar* menuBar)
{
    Row row;
    QStringList keys;
    for (const QKeySequence& sequence : action->shortcuts())
        keys << sequence.toString(QKeySequence::NativeText);
    row.keys = keys.join(QStringLiteral(", "));
    row.command = plainText(action->text());
    const auto context = action->shortcutContext();
    if (context == Qt::WidgetShortcut || context == Qt::WidgetWithChildrenShortcut) {
        // A panel's own keys work only while it has focus: say which panel.
        auto* owner = qobject_cast<QWidget*>(action->parent());
        const auto* dock = owner ? qobject_cast<QDockWidget*>(owner) : nullptr;
        row.where = dock ? ShortcutsDialog::tr("%1 panel").arg(dock->windowTitle())
                         : (owner ? owner->windowTitle() : QString());
        row.rank = std::numeric_limits<int>::max() - 1;
        return row;
    }
    row.where = ShortcutsDialog::tr("Window");
    row.rank = std::numeric_limits<int>::max() - 2;
    for (QObject* object : action->associatedObjects()) {
        auto* menu = qobject_cast<QMenu*>(object);
        if (!menu)
            continue;
        row.where = ShortcutsDialog::tr("%1 menu").arg(plainText(menu->title()));
        if (QMenu* top = topMenu(menu); top && menuBar)
            row.rank = int(menuBar->actions().indexOf(top->menuAction()));
        break;
    }
    return row;
}

} // namespace

ShortcutsDialog::ShortcutsDialog(QWidget* window, QWidget* parent)
    : QDialog(parent)
{
    setObjectName(QStringLiteral("shortcutsDialog"));
    setWindowTitle(tr("Keyboard shortcuts"));
    setAttribute(Qt::WA_DeleteOnClose);

    std::vector<Row> rows;
    const QMenuBar* menuBar = window ? window->findChild<QMenuBar*>() : nullptr;
    if (window)
        for (QAction* action : window->findChildren<QAction*>())
            if (!action->shortcuts().isEmpty())
                rows.push_back(rowFor(action, menuBar));
    // Stable: within a menu, the order the window made its actions in, which is the menu's own order.
    std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.rank < b.rank; });
    for (const auto& [keys, meaning] : ViewportWidget::inputBindings())
        rows.push_back({ keys, meaning, tr("Viewport"), std::numeric_limits<int>::max() });

    m_table = new QTableWidget(int(rows.size()), 3);
    m_table->setObjectName(QStringLiteral("shortcutsTable"));
    m_table->setHorizontalHeaderLabels({ tr("Keys"), tr("Command"), tr("Where") });
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setWordWrap(false);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        m_table->setItem(int(i), 0, new QTableWidgetItem(rows[i].keys));
        m_table->setItem(int(i), 1, new QTableWidgetItem(rows[i].command));
        m_table->setItem(int(i), 2, new QTableWidgetItem(rows[i].where));
    }
    m_table->resizeColumnsToContents();
    m_table->horizontalHeader()->setStretchLastSection(true);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_table);
    layout->addWidget(buttons);
    resize(560, 620);
}

ShortcutsDialog* ShortcutsDialog::showFor(QWidget* window)
{
    auto* dialog
        = window ? window->findChild<ShortcutsDialog*>(QString(), Qt::FindDirectChildrenOnly) : nullptr;
    if (!dialog)
        dialog = new ShortcutsDialog(window, window);
    dialog->show();
    dialog->raise();
    dialog->activateWindow();
    return dialog;
}

} // namespace vct::ui
