#pragma once
// The Help menu: Keyboard Shortcuts (every shortcut of the window's actions, read from the actions
// themselves, so that the list never goes stale), User Guide (the README, which is the manual,
// shown in a window) and About Lucerna (the version and the libraries it is built on). The
// windows are not modal: the designer keeps working beside them.

#include <QObject>
#include <QString>
#include <QStringList>

#include <vector>

class QMainWindow;
class QMenu;

namespace lucerna {

class WindowMessages;

// One row of the shortcuts window: where the action is, what it is called, its keys.
struct ShortcutRow {
    QString place;    // the menu ("Edit"), or "Window" for an action outside the menus
    QString command;  // its text without the mnemonic's &
    QString keys;     // every shortcut, in the platform's notation, comma-separated
};

class HelpActions : public QObject {
    Q_OBJECT
public:
    // A child of `window`.
    HelpActions(QMainWindow& window, WindowMessages& messages);

    // Adds Keyboard Shortcuts, User Guide and About Lucerna to `menu`.
    void addTo(QMenu* menu);

    // Every action of the window's menu bar (submenus too) and of the window itself that has a
    // shortcut, in menu order, each once.
    std::vector<ShortcutRow> shortcutRows() const;
    // The README to show: beside the bundled resources (an installed package) or at the top of
    // the source tree they come from (a build tree); "" when neither has one.
    static QString userGuidePath();
    // "Lucerna VERSION" and the libraries with their versions, one per line.
    static QStringList aboutLines();

    // The windows (objectNames shortcutsDialog, userGuideDialog, aboutDialog); the user guide
    // fails with a status line when there is no README to show.
    void showShortcuts();
    bool showUserGuide();
    void showAbout();

private:
    QMainWindow& window_;
    WindowMessages& messages_;
};

}  // namespace lucerna
