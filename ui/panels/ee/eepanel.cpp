#include "ui/panels/ee/eepanel.h"

#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "core/report/verificationjournal.h"
#include "ui/report/guijournal.h"
#include "ui/workspace/driveparameters.h"

#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

namespace dd {

EePanel::EePanel(const DriveContext &context, QWidget *parent)
    : DrivePanel(context, parent)
{
    m_intro = new QLabel(this);
    m_intro->setWordWrap(true);
    m_box = new QGroupBox(this);
    auto *grid = new QGridLayout(m_box);
    grid->setColumnStretch(1, 1);
    int row = 0;
    for (EeOperation op : operations()) {
        auto *button = new QPushButton(eeMnemonic(op), m_box);
        button->setObjectName(QStringLiteral("eeButton%1").arg(int(op)));
        button->setMinimumWidth(90);
        connect(button, &QPushButton::clicked, this, [this, op] { runOperation(op); });
        auto *meaning = new QLabel(m_box);
        meaning->setStyleSheet(QStringLiteral("font-weight: bold;"));
        auto *explanation = new QLabel(m_box);
        explanation->setWordWrap(true);
        m_buttons.insert(op, button);
        m_meanings.insert(op, meaning);
        m_explanations.insert(op, explanation);
        grid->addWidget(button, row, 0, 2, 1, Qt::AlignTop);
        grid->addWidget(meaning, row, 1);
        grid->addWidget(explanation, row + 1, 1);
        row += 2;
    }
    m_reason = new QLabel(this);
    m_reason->setObjectName(QStringLiteral("eeUnavailableReason"));
    m_reason->setWordWrap(true);
    m_reason->setStyleSheet(QStringLiteral("color: #c62828;"));
    m_progress = createProgressBar(this);
    m_progress->setObjectName(QStringLiteral("eeProgress"));
    m_progress->setRange(0, 0); // the drive reports only "running" or "done"
    m_message = createMessageLabel(this, QStringLiteral("eeMessage"));
    m_tick.setInterval(100);
    connect(&m_tick, &QTimer::timeout, this, &EePanel::updateElapsed);

    auto *bottom = new QHBoxLayout;
    bottom->addWidget(m_progress);
    bottom->addWidget(m_message, 1);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_intro);
    layout->addWidget(m_reason);
    layout->addWidget(m_box);
    layout->addLayout(bottom);
    layout->addStretch(1);

    retranslate();
}

QString EePanel::title() const
{
    return tr("EEPROM");
}

QList<EeOperation> EePanel::operations()
{
    return {EeOperation::Save, EeOperation::Reload, EeOperation::Backup, EeOperation::RestoreBackup,
            EeOperation::FactoryDefaults};
}

QString EePanel::explanation(EeOperation op)
{
    switch (op) {
    case EeOperation::Save:
        return tr("Makes the working values permanent: the drive keeps them after a power cycle. "
                  "Do this after changing parameters.");
    case EeOperation::Reload:
        return tr("Replaces the working values with those stored in EEPROM. Changes not yet stored "
                  "are lost.");
    case EeOperation::Backup:
        return tr("Copies the working values into the drive's own backup area, replacing the "
                  "previous copy there.");
    case EeOperation::RestoreBackup:
        return tr("Replaces the working values with the copy in the drive's backup area. Changes "
                  "not yet stored are lost; store the result with EE-Set to keep it after a power cycle.");
    case EeOperation::FactoryDefaults:
        return tr("Sets the working values and the EEPROM to the factory defaults. Every setting made "
                  "on this drive is lost, possibly its address and baud rate too: save a backup file "
                  "first (Backup tab).");
    }
    return {};
}

QString EePanel::message() const
{
    return m_message->text();
}

bool EePanel::confirm(EeOperation op)
{
    QMessageBox box(QMessageBox::Warning, tr("%1: %2").arg(eeMnemonic(op), eeMeaning(op)),
                    explanation(op) + QLatin1String("\n\n")
                        + tr("Run %1 on drive %2 now?").arg(eeMnemonic(op)).arg(context().address),
                    QMessageBox::Yes | QMessageBox::Cancel, this);
    box.setObjectName(QStringLiteral("eeConfirmation"));
    box.setDefaultButton(QMessageBox::Cancel);
    return box.exec() == QMessageBox::Yes;
}

void EePanel::runOperation(EeOperation op)
{
    if (isBusy() || !context().isValid() || !context().can(Capability::EeOperations))
        return;
    if (eeIsDestructive(op) && !confirm(op)) {
        setMessage(tr("%1 cancelled: nothing was sent to the drive.").arg(eeMnemonic(op)), MessageKind::Info);
        return;
    }
    m_running = op;
    m_clock.start();
    m_tick.start();
    m_progress->show();
    updateElapsed();
    updateActions();
    emit operationStarted(op);
    QPointer<EePanel> self(this);
    context().hub->run(
        context().connectionId, context().address, [op](Drive &d) { return d.eeOperation(op); },
        [self, op](const DriveResult &r) {
            if (self)
                self->onFinished(op, r);
        });
}

void EePanel::updateElapsed()
{
    if (!m_running)
        return;
    setMessage(tr("%1 running (%2 s): waiting for the drive to report completion. Do not switch "
                  "the drive off.")
                   .arg(eeMnemonic(*m_running))
                   .arg(QLocale().toString(m_clock.elapsed() / 1000.0, 'f', 1)),
               MessageKind::Info);
}

void EePanel::onFinished(EeOperation op, const DriveResult &result)
{
    m_running.reset();
    m_tick.stop();
    m_progress->hide();
    const double seconds = m_clock.elapsed() / 1000.0;
    // For the commissioning record (ui/report/guijournal.h).
    const Error journal = GuiJournal::eeOperation(context(), result.identity,
                                                  VerificationJournal::fromEe(op, result.error));
    // Made again after a language switch (LiveText).
    if (!reportResult(result)) {
        const QString error = (result.error.message + QLatin1Char(' ') + journal.message).trimmed();
        showMessage(
            m_message,
            [op, seconds, error] {
                return tr("%1 failed after %2 s: %3").arg(eeMnemonic(op), QLocale().toString(seconds, 'f', 1), error);
            },
            MessageKind::Problem);
    } else {
        const bool replaces = op == EeOperation::Reload || op == EeOperation::RestoreBackup
            || op == EeOperation::FactoryDefaults;
        showMessage(
            m_message,
            [op, seconds, replaces, journal = journal.message] {
                QString text = tr("%1 done (%2 s): %3.")
                                   .arg(eeMnemonic(op), QLocale().toString(seconds, 'f', 1), eeMeaning(op));
                if (replaces)
                    text += QLatin1Char(' ')
                        + tr("The drive now works with other values: the Parameters tab reads them again.");
                if (!journal.isEmpty())
                    text += QLatin1Char(' ') + journal;
                return text;
            },
            journal ? MessageKind::Problem : MessageKind::Success);
        if (replaces)
            parameters()->reportValuesReplaced(op == EeOperation::Reload); // EE-rd: values = EEPROM
        else if (op == EeOperation::Save)
            parameters()->reportSaved();
    }
    updateActions();
    emit operationFinished(op, result.ok());
}

void EePanel::setMessage(const QString &text, MessageKind kind)
{
    showMessage(m_message, text, kind);
}

void EePanel::updateActions()
{
    const bool can = context().can(Capability::EeOperations);
    for (QPushButton *b : std::as_const(m_buttons))
        b->setEnabled(can && !isBusy());
    QString reason;
    if (!can) {
        reason = driveInfo().reason(Capability::EeOperations);
        if (reason.isEmpty())
            reason = driveInfo().valid ? tr("This drive has no EEPROM operations.")
                                       : tr("Waiting for the drive's identity…");
    }
    m_reason->setText(reason);
    m_reason->setVisible(!reason.isEmpty());
}

void EePanel::driveInfoChanged(const DriveInfo &)
{
    updateActions();
}

void EePanel::retranslate()
{
    m_intro->setText(tr("The drive works with its working values; EEPROM keeps a copy over a power "
                        "cycle, and a backup area holds a second copy. Parameter writes change only the "
                        "working values."));
    m_box->setTitle(tr("EEPROM operations"));
    for (EeOperation op : operations()) {
        QString meaning = eeMeaning(op);
        if (eeIsDestructive(op))
            meaning += QStringLiteral(" — ") + tr("asks for confirmation");
        m_meanings.value(op)->setText(meaning);
        m_explanations.value(op)->setText(explanation(op));
        m_buttons.value(op)->setToolTip(eeMeaning(op));
    }
    updateActions();
    updateElapsed();
}

} // namespace dd
