#include "ui/help/userguidedialog.h"

#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QEvent>
#include <QFile>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace dd {

UserGuideDialog::UserGuideDialog(QWidget *parent)
    : QDialog(parent)
{
    setObjectName(QStringLiteral("userGuideDialog"));
    m_browser = new QTextBrowser(this);
    m_browser->setObjectName(QStringLiteral("userGuideText"));
    m_browser->setOpenLinks(false);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_browser, 1);
    layout->addWidget(buttons);
    resize(720, 600);
    retranslate();
}

QString UserGuideDialog::guidePath()
{
    // The language DriveDesk's translation says it is in (the translator's own entry).
    const bool chinese = QCoreApplication::translate("dd::UserGuideDialog", "userguide-en.md")
                             .contains(QLatin1String("zh_CN"));
    return chinese ? QStringLiteral(":/help/userguide-zh_CN.md") : QStringLiteral(":/help/userguide-en.md");
}

QString UserGuideDialog::guideText() const
{
    return m_browser->toPlainText();
}

void UserGuideDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void UserGuideDialog::retranslate()
{
    setWindowTitle(tr("DriveDesk user guide"));
    QFile file(guidePath());
    if (file.open(QIODevice::ReadOnly))
        m_browser->setMarkdown(QString::fromUtf8(file.readAll()));
    else
        m_browser->setPlainText(tr("The user guide is missing from this build."));
}

} // namespace dd
