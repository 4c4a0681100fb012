// oneTBB before any Qt header: Qt's `emit` macro breaks TBB's headers.
#include <oneapi/tbb/version.h>

#include "ui/window/help_actions.h"

#include "core/resources.h"
#include "ui/window/menu_entry.h"
#include "ui/window/window_messages.h"

#include <Imath/ImathConfig.h>

#include <QAction>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QSet>
#include <QTableWidget>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <functional>

namespace lucerna {

namespace {
QString withoutMnemonic(QString text) {
    text.remove(QRegularExpression(QStringLiteral("&(?!&)")));
    return text.replace(QStringLiteral("&&"), QStringLiteral("&"));
}

// A window with `content` and a Close button, deleted when closed.
QDialog* toolWindow(QMainWindow& parent, const QString& name, const QString& title, QWidget* content, QSize size) {
    auto* dialog = new QDialog(&parent);
    dialog->setObjectName(name);
    dialog->setWindowTitle(title);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    auto* layout = new QVBoxLayout(dialog);
    content->setParent(dialog);
    layout->addWidget(content);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);
    layout->addWidget(buttons);
    dialog->resize(size);
    dialog->show();
    return dialog;
}
}  // namespace

HelpActions::HelpActions(QMainWindow& window, WindowMessages& messages)
    : QObject(&window), window_(window), messages_(messages) {}

void HelpActions::addTo(QMenu* menu) {
    addMenuEntry(menu, tr("&Keyboard Shortcuts"), "actionKeyboardShortcuts", QKeySequence(), this,
                 [this] { showShortcuts(); });
    addMenuEntry(menu, tr("&User Guide"), "actionUserGuide", QKeySequence::HelpContents, this,
                 [this] { showUserGuide(); });
    menu->addSeparator();
    addMenuEntry(menu, tr("&About Lucerna"), "actionAbout", QKeySequence(), this, [this] { showAbout(); });
}

std::vector<ShortcutRow> HelpActions::shortcutRows() const {
    std::vector<ShortcutRow> rows;
    QSet<const QAction*> seen;
    const auto add = [&](const QAction* a, const QString& place) {
        if (a->isSeparator() || a->shortcuts().isEmpty() || seen.contains(a)) return;
        seen.insert(a);
        QStringList keys;
        for (const QKeySequence& k : a->shortcuts()) keys << k.toString(QKeySequence::NativeText);
        rows.push_back({place, withoutMnemonic(a->text()), keys.join(QStringLiteral(", "))});
    };
    // Depth first, in the order the menus show their entries.
    const std::function<void(const QMenu*, const QString&)> walk = [&](const QMenu* menu, const QString& place) {
        for (const QAction* a : menu->actions()) {
            if (const QMenu* sub = a->menu()) walk(sub, place + QStringLiteral(" > ") + withoutMnemonic(sub->title()));
            else add(a, place);
        }
    };
    for (const QAction* a : window_.menuBar()->actions())
        if (const QMenu* menu = a->menu()) walk(menu, withoutMnemonic(menu->title()));
    for (const QAction* a : window_.actions()) add(a, tr("Window"));
    return rows;
}

void HelpActions::showShortcuts() {
    const std::vector<ShortcutRow> rows = shortcutRows();
    auto* table = new QTableWidget(int(rows.size()), 3);
    table->setObjectName("shortcutsTable");
    table->setHorizontalHeaderLabels({tr("Menu"), tr("Command"), tr("Keys")});
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->setSelectionBehavior(QAbstractItemView::SelectRows);
    table->verticalHeader()->hide();
    for (int i = 0; i < int(rows.size()); ++i) {
        const ShortcutRow& r = rows[size_t(i)];
        table->setItem(i, 0, new QTableWidgetItem(r.place));
        table->setItem(i, 1, new QTableWidgetItem(r.command));
        table->setItem(i, 2, new QTableWidgetItem(r.keys));
    }
    table->resizeColumnsToContents();
    table->horizontalHeader()->setStretchLastSection(true);
    toolWindow(window_, "shortcutsDialog", tr("Keyboard Shortcuts"), table, QSize(640, 620));
}

QString HelpActions::userGuidePath() {
    const QDir resources(QString::fromStdString(resourceDirectory()));
    for (const QString& candidate : {resources.filePath("README.md"), resources.filePath("../README.md")})
        if (QFileInfo(candidate).isFile()) return QDir::cleanPath(candidate);
    return {};
}

bool HelpActions::showUserGuide() {
    const QString path = userGuidePath();
    QFile file(path);
    if (path.isEmpty() || !file.open(QIODevice::ReadOnly))
        return messages_.fail(path.isEmpty() ? tr("The user guide (README.md) is not installed beside %1")
                                                   .arg(QString::fromStdString(resourceDirectory()))
                                             : tr("Could not read the user guide %1").arg(path));
    auto* browser = new QTextBrowser;
    browser->setObjectName("userGuideText");
    browser->setOpenExternalLinks(true);
    // Pictures and links relative to the README.
    browser->setSearchPaths({QFileInfo(path).absolutePath()});
    browser->setMarkdown(QString::fromUtf8(file.readAll()));
    toolWindow(window_, "userGuideDialog", tr("Lucerna User Guide"), browser, QSize(900, 760));
    return true;
}

QStringList HelpActions::aboutLines() {
    QStringList lines{QStringLiteral("Lucerna %1").arg(QStringLiteral(LUCERNA_VERSION))};
    const std::pair<const char*, QString> libraries[] = {
        {"Qt", QString::fromLatin1(qVersion())},
        {"Embree", QStringLiteral(LUCERNA_EMBREE_VERSION)},
        {"oneTBB", QStringLiteral(TBB_VERSION_STRING)},
        {"OpenEXR", QStringLiteral(LUCERNA_OPENEXR_VERSION)},
        {"Imath", QStringLiteral(IMATH_VERSION_STRING)},
        {"Assimp", QStringLiteral(LUCERNA_ASSIMP_VERSION)},
    };
    for (const auto& [name, version] : libraries)
        lines << (version.isEmpty() ? QString::fromLatin1(name) : QStringLiteral("%1 %2").arg(QLatin1String(name), version));
    return lines;
}

void HelpActions::showAbout() {
    const QStringList lines = aboutLines();
    auto* label = new QLabel;
    label->setObjectName("aboutText");
    label->setTextFormat(Qt::RichText);
    label->setWordWrap(true);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    label->setText(tr("<h3>%1</h3><p>Lighting design with a live preview beside a converging physically based "
                      "render.</p><p>Built with %2.</p>")
                       .arg(lines.first().toHtmlEscaped(), lines.mid(1).join(QStringLiteral(", ")).toHtmlEscaped()));
    toolWindow(window_, "aboutDialog", tr("About Lucerna"), label, QSize(460, 220));
}

}  // namespace lucerna
