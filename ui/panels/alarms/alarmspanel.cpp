#include "ui/panels/alarms/alarmspanel.h"

#include "core/common/csvfield.h"
#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "core/drive/drivereply.h"
#include "ui/common/displaytext.h"

#include <QDir>
#include <QFileDialog>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPointer>
#include <QPushButton>
#include <QSaveFile>
#include <QTableWidget>
#include <QVBoxLayout>

namespace dd {

AlarmsPanel::AlarmsPanel(const DriveContext &context, QWidget *parent)
    : DrivePanel(context, parent)
{
    // The user's table (AppData/alarms/<family>.json) if valid, else the bundled one.
    const Error dictionaryError = m_dictionary.loadForFamily(context.family);

    buildCurrentBox();
    buildHistoryBox();
    connect(alarmLog(), &AlarmLog::changed, this, [this] {
        showCurrent();
        showHistory();
    });
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_currentBox);
    layout->addWidget(m_historyBox, 1);

    retranslate();
    reportError(dictionaryError);
}

void AlarmsPanel::buildCurrentBox()
{
    m_currentBox = new QGroupBox(this);
    m_codeLabel = new QLabel(m_currentBox);
    m_codeLabel->setObjectName(QStringLiteral("alarmCode"));
    QFont big = m_codeLabel->font();
    big.setPointSizeF(big.pointSizeF() * 1.5);
    big.setBold(true);
    m_codeLabel->setFont(big);
    m_textLabel = new QLabel(m_currentBox);
    m_textLabel->setObjectName(QStringLiteral("alarmText"));
    m_textLabel->setWordWrap(true);
    m_textLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_remedyLabel = new QLabel(m_currentBox);
    m_remedyLabel->setObjectName(QStringLiteral("alarmRemedy"));
    m_remedyLabel->setWordWrap(true);
    m_read = new QPushButton(m_currentBox);
    m_read->setObjectName(QStringLiteral("readAlarmButton"));
    m_clear = new QPushButton(m_currentBox);
    m_clear->setObjectName(QStringLiteral("clearAlarmButton"));
    m_clearReason = createReasonLabel(m_currentBox);
    m_clearReason->setObjectName(QStringLiteral("clearAlarmReason"));
    connect(m_read, &QPushButton::clicked, this, &AlarmsPanel::readAlarm);
    connect(m_clear, &QPushButton::clicked, this, &AlarmsPanel::clearAlarm);

    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_read);
    buttons->addWidget(m_clear);
    buttons->addStretch(1);
    auto *current = new QVBoxLayout(m_currentBox);
    current->addWidget(m_codeLabel);
    current->addWidget(m_textLabel);
    current->addWidget(m_remedyLabel);
    current->addLayout(buttons);
    current->addWidget(m_clearReason);
}

void AlarmsPanel::buildHistoryBox()
{
    m_historyBox = new QGroupBox(this);
    m_table = new QTableWidget(m_historyBox);
    m_table->setObjectName(QStringLiteral("alarmHistory"));
    m_table->setColumnCount(3);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_export = new QPushButton(m_historyBox);
    m_export->setObjectName(QStringLiteral("exportAlarmsButton"));
    m_forget = new QPushButton(m_historyBox);
    m_forget->setObjectName(QStringLiteral("forgetAlarmsButton"));
    connect(m_export, &QPushButton::clicked, this, &AlarmsPanel::exportWithDialog);
    connect(m_forget, &QPushButton::clicked, alarmLog(), &AlarmLog::clearHistory);
    auto *historyButtons = new QHBoxLayout;
    historyButtons->addStretch(1);
    historyButtons->addWidget(m_forget);
    historyButtons->addWidget(m_export);
    auto *history = new QVBoxLayout(m_historyBox);
    history->addWidget(m_table, 1);
    history->addLayout(historyButtons);
}

QString AlarmsPanel::title() const
{
    return tr("Alarms");
}

QString AlarmsPanel::alarmText(int code) const
{
    if (code == 0)
        return tr("No alarm");
    if (m_dictionary.isLoaded())
        return m_dictionary.text(code, QLocale());
    return DisplayText::alarm(code);
}

void AlarmsPanel::readAlarm()
{
    if (!context().isValid() || !context().can(Capability::ReadAlarm))
        return;
    m_readOnce = true;
    m_read->setEnabled(false);
    QPointer<AlarmsPanel> self(this);
    const quint64 eventsBefore = m_alarmEvents;
    context().hub->run(
        context().connectionId, context().address, [](Drive &d) { return d.readAlarm(); },
        [self, eventsBefore](const DriveResult &r) {
            if (!self)
                return;
            self->updateCapabilities();
            // An alarm change the drive reported while the read was on its way is newer than
            // the read's answer (which may have left the drive before the change): keep it.
            if (self->reportResult(r) && self->m_alarmEvents == eventsBefore)
                self->onCode(r.status.alarmCode);
        });
}

void AlarmsPanel::clearAlarm()
{
    if (!context().isValid() || !context().can(Capability::ClearAlarm))
        return;
    m_clear->setEnabled(false);
    QPointer<AlarmsPanel> self(this);
    context().hub->run(
        context().connectionId, context().address, [](Drive &d) { return d.clearAlarm(); },
        [self](const DriveResult &r) {
            if (!self)
                return;
            self->updateCapabilities();
            if (self->reportResult(r))
                self->readAlarm(); // the code the drive reports now
        });
}

Error AlarmsPanel::exportHistory(const QString &path) const
{
    QByteArray bytes = "time,code,alarm\n";
    for (const HistoryEntry &e : history()) {
        QDateTime t = e.time;
        t = t.toOffsetFromUtc(t.offsetFromUtc());
        bytes += t.toString(Qt::ISODateWithMs).toLatin1() + ',' + QByteArray::number(e.code) + ','
            + csvField(alarmText(e.code)) + '\n';
    }
    const QString shown = QDir::toNativeSeparators(path);
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return {ErrorCode::FileError, tr("Cannot write %1: %2.").arg(shown, file.errorString())};
    if (file.write(bytes) != bytes.size() || !file.flush()) { // Qt 6.4: check before commit()
        const QString why = file.errorString();
        file.cancelWriting();
        return {ErrorCode::FileError, tr("Cannot write %1: %2.").arg(shown, why)};
    }
    if (!file.commit())
        return {ErrorCode::FileError, tr("Cannot write %1: %2.").arg(shown, file.errorString())};
    return Error::none();
}

void AlarmsPanel::exportWithDialog()
{
    const QString name = QStringLiteral("alarms-%1-%2.csv")
                             .arg(familyId(context().family))
                             .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")));
    const QString path = QFileDialog::getSaveFileName(this, tr("Export alarm history"), QDir::home().filePath(name),
                                                      tr("CSV files (*.csv)"));
    if (path.isEmpty())
        return;
    // Not a Recent file: an export is not opened again.
    if (const Error e = exportHistory(path))
        reportError(e);
}

void AlarmsPanel::activeChanged(bool active)
{
    // Read once when first shown (heartbeat families report changes by themselves; the
    // others are polled by the status poller).
    if (active && !m_readOnce)
        readAlarm();
}

void AlarmsPanel::driveInfoChanged(const DriveInfo &info)
{
    updateCapabilities();
    // Only the first code comes from here: the snapshot's status may be older than the
    // alarm changes that arrived since (they come through alarmChanged()).
    if (currentCode() < 0 && (info.status.updatedMs || info.status.alarmCode))
        onCode(info.status.alarmCode);
    if (isActive() && !m_readOnce)
        readAlarm();
}

void AlarmsPanel::alarmChanged(int code)
{
    ++m_alarmEvents;
    onCode(code);
}

void AlarmsPanel::onCode(int code)
{
    alarmLog()->record(code); // shown when it changes
}

void AlarmsPanel::showCurrent()
{
    const int code = currentCode();
    if (code < 0) {
        m_codeLabel->setText(QStringLiteral("—"));
        m_codeLabel->setStyleSheet(QString());
        m_textLabel->setText(tr("Not read yet."));
        m_remedyLabel->hide();
        return;
    }
    m_codeLabel->setText(code ? tr("Alarm %1").arg(code) : tr("No alarm"));
    m_codeLabel->setStyleSheet(code ? QStringLiteral("color: #c62828;") : QStringLiteral("color: #2e7d32;"));
    m_textLabel->setText(code ? alarmText(code) : tr("The drive reports no alarm."));
    QString remedy = code && m_dictionary.isLoaded() ? m_dictionary.remedy(code, QLocale()) : QString();
    if (code && remedy.isEmpty() && !(m_dictionary.isLoaded() && m_dictionary.contains(code)))
        remedy = tr("the alarm table knows no code %1: see the drive's manual. To name it here, put your "
                    "own table at %2 (format: docs/dictionaries.md).")
                     .arg(code)
                     .arg(QDir::toNativeSeparators(AlarmDictionary::userFilePath(context().family)));
    m_remedyLabel->setText(tr("What to check: %1").arg(remedy));
    m_remedyLabel->setVisible(!remedy.isEmpty());
}

void AlarmsPanel::showHistory()
{
    const QList<HistoryEntry> &entries = history();
    m_table->setRowCount(int(entries.size()));
    const QLocale locale;
    for (int i = 0; i < entries.size(); ++i) {
        const HistoryEntry &e = entries.at(entries.size() - 1 - i); // newest first
        auto *time = new QTableWidgetItem(locale.toString(e.time, QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz")));
        auto *code = new QTableWidgetItem(QString::number(e.code));
        code->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        auto *text = new QTableWidgetItem(e.code ? alarmText(e.code) : tr("Alarm cleared"));
        if (e.code)
            text->setForeground(QColor(0xc6, 0x28, 0x28));
        m_table->setItem(i, 0, time);
        m_table->setItem(i, 1, code);
        m_table->setItem(i, 2, text);
    }
    m_export->setEnabled(!entries.isEmpty());
    m_forget->setEnabled(!entries.isEmpty());
}

void AlarmsPanel::updateCapabilities()
{
    const DriveInfo &info = driveInfo();
    const QString waiting = tr("Waiting for the drive's description…");
    const QString readReason = context().can(Capability::ReadAlarm)
        ? QString()
        : (info.valid ? info.reason(Capability::ReadAlarm) : waiting);
    const QString clearReason = context().can(Capability::ClearAlarm)
        ? QString()
        : (info.valid ? info.reason(Capability::ClearAlarm) : waiting);
    m_read->setEnabled(readReason.isEmpty());
    m_read->setToolTip(readReason.isEmpty() ? tr("Ask the drive for its current alarm code") : readReason);
    m_clear->setEnabled(clearReason.isEmpty());
    m_clear->setToolTip(clearReason.isEmpty() ? tr("Reset the drive's alarm (the cause must be gone)") : clearReason);
    m_clearReason->setText(clearReason);
    m_clearReason->setVisible(!clearReason.isEmpty() && clearReason != waiting);
}

void AlarmsPanel::retranslate()
{
    m_currentBox->setTitle(tr("Current alarm"));
    m_historyBox->setTitle(tr("History"));
    m_read->setText(tr("&Read alarm"));
    m_clear->setText(tr("&Clear alarm"));
    m_export->setText(tr("&Export…"));
    m_forget->setText(tr("Clear &list"));
    m_table->setHorizontalHeaderLabels({tr("Time"), tr("Code"), tr("Alarm")});
    updateCapabilities();
    showCurrent();
    showHistory();
}

} // namespace dd
