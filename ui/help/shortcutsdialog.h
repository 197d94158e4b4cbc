#pragma once

#include <QDialog>

class QTableWidget;

namespace dd {

// Help → Keyboard shortcuts: every key DriveDesk reacts to, what it does and where, in the
// current language.
class ShortcutsDialog : public QDialog
{
    Q_OBJECT
public:
    explicit ShortcutsDialog(QWidget *parent = nullptr);

    QTableWidget *table() const { return m_table; }

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    QTableWidget *m_table = nullptr;
};

} // namespace dd
