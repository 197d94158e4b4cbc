#pragma once

#include <QDialog>

class QTextBrowser;

namespace dd {

// Help → User guide (F1): a short guide bundled with the program (:/help/userguide-<lang>.md,
// English and Chinese), in the current language, again after a language switch.
class UserGuideDialog : public QDialog
{
    Q_OBJECT
public:
    explicit UserGuideDialog(QWidget *parent = nullptr);

    // The guide's resource for the UI language now ("…-zh_CN.md" when it is Chinese).
    static QString guidePath();
    QString guideText() const; // as shown, plain

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    QTextBrowser *m_browser = nullptr;
};

} // namespace dd
