#include "ui/bus/serialaccessdialog.h"

#include <QClipboard>
#include <QDialogButtonBox>
#include <QEvent>
#include <QFontDatabase>
#include <QGuiApplication>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QStyle>
#include <QVBoxLayout>

namespace dd {

SerialAccessDialog::SerialAccessDialog(const SerialAccessProblem &problem, QWidget *parent)
    : QDialog(parent)
    , m_problem(problem)
{
    setObjectName(QStringLiteral("serialAccessDialog"));
    auto *layout = new QVBoxLayout(this);
    auto *row = new QHBoxLayout;
    auto *icon = new QLabel(this);
    const int size = style()->pixelMetric(QStyle::PM_MessageBoxIconSize, nullptr, this);
    icon->setPixmap(style()->standardIcon(QStyle::SP_MessageBoxWarning, nullptr, this).pixmap(size, size));
    icon->setAlignment(Qt::AlignTop);
    row->addWidget(icon);
    m_text = new QLabel(this);
    m_text->setWordWrap(true);
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    row->addWidget(m_text, 1);
    layout->addLayout(row);

    m_command = new QLineEdit(m_problem.command(), this);
    m_command->setObjectName(QStringLiteral("serialAccessCommand"));
    m_command->setReadOnly(true);
    m_command->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    layout->addWidget(m_command);
    m_after = new QLabel(this);
    m_after->setWordWrap(true);
    layout->addWidget(m_after);

    m_buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    m_copy = m_buttons->addButton(QString(), QDialogButtonBox::ActionRole);
    m_copy->setObjectName(QStringLiteral("copyCommandButton"));
    connect(m_copy, &QPushButton::clicked, this, &SerialAccessDialog::copyCommand);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(m_buttons);

    const bool hasCommand = !m_problem.command().isEmpty() && !m_problem.alreadyMember;
    m_command->setVisible(hasCommand);
    m_after->setVisible(hasCommand);
    m_copy->setVisible(hasCommand);
    if (hasCommand)
        m_copy->setDefault(true);
    retranslate();
    resize(qMax(sizeHint().width(), 520), sizeHint().height());
}

void SerialAccessDialog::copyCommand()
{
    QGuiApplication::clipboard()->setText(m_problem.command());
    m_copy->setText(tr("Copied"));
}

void SerialAccessDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void SerialAccessDialog::retranslate()
{
    setWindowTitle(tr("No permission for %1").arg(m_problem.port));
    if (m_command->isVisibleTo(this))
        m_text->setText(tr("You may not use the serial port %1: it belongs to the group '%2', and you are not a "
                           "member. Add yourself once, in a terminal:")
                            .arg(m_problem.port, m_problem.group));
    else
        m_text->setText(m_problem.message());
    m_after->setText(tr("Then log out and log in again (or restart the computer), so that the new group takes "
                        "effect, and connect again."));
    m_copy->setText(tr("&Copy command"));
}

} // namespace dd
