#include "ui/shell/aboutdialog.h"

#include "core/common/family.h"

#include <QApplication>
#include <QDialogButtonBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QIcon>
#include <QLabel>
#include <QVBoxLayout>

namespace dd {

AboutDialog::AboutDialog(QWidget *parent)
    : QDialog(parent)
{
    setObjectName(QStringLiteral("aboutDialog"));
    auto *layout = new QVBoxLayout(this);
    auto *row = new QHBoxLayout;
    m_icon = new QLabel(this);
    const QIcon icon = QApplication::windowIcon();
    if (!icon.isNull())
        m_icon->setPixmap(icon.pixmap(64, 64));
    m_icon->setAlignment(Qt::AlignTop);
    row->addWidget(m_icon);
    m_text = new QLabel(this);
    m_text->setObjectName(QStringLiteral("aboutText"));
    m_text->setWordWrap(true);
    m_text->setTextFormat(Qt::RichText);
    m_text->setOpenExternalLinks(true);
    m_text->setTextInteractionFlags(Qt::TextBrowserInteraction);
    row->addWidget(m_text, 1);
    layout->addLayout(row);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(m_buttons);
    retranslate();
    setMinimumWidth(460);
}

QString AboutDialog::text() const
{
    return m_text->text();
}

void AboutDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void AboutDialog::retranslate()
{
    setWindowTitle(tr("About DriveDesk"));
    // Qt at run time, and the one it was built with when they differ (a newer Qt 6 library).
    QString qt = QString::fromLatin1(qVersion());
    if (qt != QLatin1String(QT_VERSION_STR))
        qt = tr("%1 (built with %2)").arg(qt, QLatin1String(QT_VERSION_STR));
    m_text->setText(
        tr("<h3>DriveDesk %1</h3>"
           "<p>Commissioning and tuning workbench for servo and stepper drives over RS485 / RS232 and CAN.</p>"
           "<p>Drive families: %2.</p>"
           "<p>Qt %3.</p>"
           "<p>DriveDesk is free software: you can redistribute it and modify it under the terms of the GNU "
           "General Public License, version 3 or (at your option) any later version. It comes with "
           "ABSOLUTELY NO WARRANTY. See the LICENSE file, or "
           "<a href=\"https://www.gnu.org/licenses/gpl-3.0.html\">gnu.org/licenses/gpl-3.0</a>.</p>")
            .arg(QStringLiteral(DRIVEDESK_VERSION), familyIds().join(QStringLiteral(", ")), qt));
}

} // namespace dd
