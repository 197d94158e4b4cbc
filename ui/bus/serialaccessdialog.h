#pragma once

#include "core/link/serialaccess.h"

#include <QDialog>

class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace dd {

// "Permission denied" on a serial port: what is wrong, the command that fixes it (selectable,
// with a button that copies it), and that the user must log in again afterwards.
class SerialAccessDialog : public QDialog
{
    Q_OBJECT
public:
    explicit SerialAccessDialog(const SerialAccessProblem &problem, QWidget *parent = nullptr);

    const SerialAccessProblem &problem() const { return m_problem; }
    QPushButton *copyButton() const { return m_copy; }

protected:
    void changeEvent(QEvent *event) override;

private:
    void copyCommand();
    void retranslate();

    SerialAccessProblem m_problem;
    QLabel *m_text = nullptr;
    QLineEdit *m_command = nullptr;
    QLabel *m_after = nullptr;
    QPushButton *m_copy = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
};

} // namespace dd
