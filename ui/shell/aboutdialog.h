#pragma once

#include <QDialog>

class QDialogButtonBox;
class QLabel;

namespace dd {

// Help → About DriveDesk: the version, the Qt version it runs on (and was built with), the
// drive families and the licence (GPL-3.0-or-later, LICENSE), translated.
class AboutDialog : public QDialog
{
    Q_OBJECT
public:
    explicit AboutDialog(QWidget *parent = nullptr);

    QString text() const; // the body, for tests

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    QLabel *m_icon = nullptr;
    QLabel *m_text = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
};

} // namespace dd
