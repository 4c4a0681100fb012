#pragma once
// The daylight dock's clock field: a QTimeEdit ("HH:mm") into which a typed time lands from the
// hour on. Qt's own field leaves a click with a bare cursor and no section selected; digits typed
// there are inserted into the full hour section, which refuses them ("812" is no hour), then the
// ':' moves on and the minutes take the rest: "18:55" typed after a click gave 12:55. Here a
// typing run starts on a selected section: the hour when the field is entered (by click or key)
// or when its whole text is selected, else the section the cursor is in; the run then goes on as
// Qt's does (two digits, ':' to the minutes). Arrow keys, Enter and clicks end a run.

#include <QTimeEdit>

namespace lucerna {

class TimeOfDayEdit : public QTimeEdit {
public:
    explicit TimeOfDayEdit(QTime time, QWidget* parent = nullptr);

protected:
    void focusInEvent(QFocusEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    // The clicks go to the line edit inside: a press ends a run, the release of the click that
    // entered the field selects the hour (the press had placed a bare cursor).
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    bool typing_ = false;          // within a run of typed characters
    bool enteredByClick_ = false;  // focus came with the click being handled
};

}  // namespace lucerna
