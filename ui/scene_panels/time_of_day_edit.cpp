#include "ui/scene_panels/time_of_day_edit.h"

#include <QFocusEvent>
#include <QKeyEvent>
#include <QLineEdit>
#include <QMouseEvent>
#include <QTimer>

namespace lucerna {

TimeOfDayEdit::TimeOfDayEdit(QTime time, QWidget* parent) : QTimeEdit(time, parent) {
    setDisplayFormat(QStringLiteral("HH:mm"));
    lineEdit()->installEventFilter(this);
}

void TimeOfDayEdit::focusInEvent(QFocusEvent* event) {
    QTimeEdit::focusInEvent(event);
    typing_ = false;
    // A click places the cursor after this; the release selects the hour again.
    enteredByClick_ = event->reason() == Qt::MouseFocusReason;
    setSelectedSection(HourSection);
}

bool TimeOfDayEdit::eventFilter(QObject* watched, QEvent* event) {
    if (watched == lineEdit()) {
        if (event->type() == QEvent::MouseButtonPress) typing_ = false;
        if (event->type() == QEvent::MouseButtonRelease && enteredByClick_) {
            enteredByClick_ = false;
            // Once the line edit has had the release (a drag may have selected text: it is kept).
            QTimer::singleShot(0, this, [this] {
                if (!lineEdit()->hasSelectedText()) setSelectedSection(HourSection);
            });
        }
    }
    return QTimeEdit::eventFilter(watched, event);
}

void TimeOfDayEdit::keyPressEvent(QKeyEvent* event) {
    const QString text = event->text();
    const bool typed = !text.isEmpty() && (text[0].isDigit() || text[0] == QLatin1Char(':'));
    if (!typed) {
        typing_ = false;
        return QTimeEdit::keyPressEvent(event);
    }
    if (!typing_ && text[0].isDigit()) {
        const QString selected = lineEdit()->selectedText();
        // The whole time (or across the ':') selected: a typed time starts at the hour.
        if (selected.contains(QLatin1Char(':'))) setSelectedSection(HourSection);
        // A bare cursor: the digits replace the section it is in.
        else if (selected.isEmpty()) setSelectedSection(currentSection());
    }
    typing_ = true;
    QTimeEdit::keyPressEvent(event);
}

}  // namespace lucerna
