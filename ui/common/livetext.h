#pragma once

#include <QObject>
#include <functional>

class QLabel;

namespace dd {

// A label text that follows a live language switch: the text is made by a function, now and
// again on every QEvent::LanguageChange (which a widget passes on to its child objects, this
// one among them). For message lines that report something done earlier ("Read 60
// parameters from the drive."), whose words must change language with the rest.
class LiveText : public QObject
{
    Q_OBJECT
public:
    // Sets the label's text from `make`, now and after every language change.
    static void set(QLabel *label, std::function<QString()> make);
    // Forgets the label's maker (call before setting a plain text).
    static void clear(QLabel *label);
    // The label's maker (empty when its text is plain).
    static std::function<QString()> maker(const QLabel *label);

protected:
    bool event(QEvent *event) override;

private:
    LiveText(QLabel *label, std::function<QString()> make);

    QLabel *m_label;
    std::function<QString()> m_make;
};

} // namespace dd
