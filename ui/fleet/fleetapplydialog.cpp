#include "ui/fleet/fleetapplydialog.h"

#include "core/params/parameterdictionary.h"
#include "core/report/verificationjournal.h"
#include "ui/bus/drivedirectory.h"
#include "ui/panels/backup/transferoperation.h"
#include "ui/report/guijournal.h"

#include <QCheckBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace dd {

FleetApplyDialog::FleetApplyDialog(DriveDirectory *directory, int connectionId, const QList<int> &targets,
                                   QWidget *parent)
    : QDialog(parent)
    , m_directory(directory)
    , m_connectionId(connectionId)
    , m_targets(targets)
{
    setObjectName(QStringLiteral("fleetApplyDialog"));
    resize(720, 520);
    m_source = new QLabel(this);
    m_source->setWordWrap(true);
    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("fleetMessage"));
    m_message->setWordWrap(true);
    m_tree = new QTreeWidget(this);
    m_tree->setObjectName(QStringLiteral("fleetPlan"));
    m_tree->setColumnCount(2);
    m_tree->header()->setStretchLastSection(true);
    m_stopAtFirst = new QCheckBox(this);
    m_stopAtFirst->setObjectName(QStringLiteral("stopAtFirstFailure"));
    m_stopAtFirst->setChecked(true);
    m_confirm = new QCheckBox(this);
    m_confirm->setObjectName(QStringLiteral("confirmEnergised"));
    m_confirm->hide();
    m_apply = new QPushButton(this);
    m_apply->setObjectName(QStringLiteral("applyButton"));
    m_apply->setEnabled(false);
    m_close = new QPushButton(this);

    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_stopAtFirst);
    buttons->addStretch(1);
    buttons->addWidget(m_apply);
    buttons->addWidget(m_close);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_source);
    layout->addWidget(m_tree, 1);
    layout->addWidget(m_confirm);
    layout->addWidget(m_message);
    layout->addLayout(buttons);

    connect(m_apply, &QPushButton::clicked, this, &FleetApplyDialog::apply);
    connect(m_close, &QPushButton::clicked, this, &QDialog::reject);
    connect(m_confirm, &QCheckBox::toggled, this, &FleetApplyDialog::updateButtons);
    for (int a : std::as_const(m_targets)) {
        auto *item = new QTreeWidgetItem(m_tree);
        item->setData(0, Qt::UserRole, a);
        m_states.insert(a, DriveState::Planning);
    }
    retranslate();
}

FleetApplyDialog::~FleetApplyDialog() = default;

void FleetApplyDialog::setSourceFile(const BackupFile &file, const QString &name, const QString &path)
{
    m_file = file;
    m_sourceName = name;
    m_sourcePath = path;
    m_hasSource = true;
    retranslate();
    plan();
}

void FleetApplyDialog::setSourceDrive(int address)
{
    m_targets.removeAll(address);
    for (int i = m_tree->topLevelItemCount() - 1; i >= 0; --i)
        if (m_tree->topLevelItem(i)->data(0, Qt::UserRole).toInt() == address)
            delete m_tree->takeTopLevelItem(i);
    m_states.remove(address);
    m_sourceName = tr("drive %1").arg(address);
    m_sourcePath.clear();
    retranslate();
    m_message->setText(tr("Reading drive %1…").arg(address));
    auto out = std::make_shared<TransferOutcome>();
    m_directory->hub()->run(
        m_connectionId, address, TransferOperation::backup(out), [this, out, address](const DriveResult &r) {
            if (r.error) {
                m_message->setText(
                    tr("Drive %1 could not be read: %2. Nothing was written.").arg(address).arg(r.error.message));
                return;
            }
            m_file = out->backup;
            m_hasSource = true;
            plan();
        });
}

void FleetApplyDialog::plan()
{
    m_message->setText(tr("Reading the drives to plan the changes; nothing is written yet…"));
    for (int a : std::as_const(m_targets)) {
        m_states[a] = DriveState::Planning;
        updateItem(a);
        RestoreOptions o;
        o.dryRun = true;
        auto out = std::make_shared<TransferOutcome>();
        m_directory->hub()->run(m_connectionId, a, TransferOperation::restore(m_file, o, out),
                                [this, out, a](const DriveResult &r) { onPlanned(a, r.error, out->report); });
    }
}

void FleetApplyDialog::onPlanned(int address, const Error &error, const RestoreReport &report)
{
    m_plans[address] = report;
    m_errors[address] = error;
    m_states[address] = error ? DriveState::PlanFailed : DriveState::Planned;
    updateItem(address);
    if (!isPlanned())
        return;
    int changes = 0;
    for (int a : std::as_const(m_targets))
        changes += int(m_plans.value(a).selected.size());
    m_message->setText(
        tr("Plan: %n parameter(s) to write in all. Only these are written; each is read back.", nullptr, changes));
    updateButtons();
    emit planReady();
}

bool FleetApplyDialog::isPlanned() const
{
    for (int a : m_targets)
        if (m_states.value(a) == DriveState::Planning)
            return false;
    return m_hasSource && !m_targets.isEmpty();
}

QList<int> FleetApplyDialog::planned(int address) const
{
    QList<int> out;
    for (const DiffEntry &e : m_plans.value(address).selected)
        out << e.index;
    return out;
}

QList<int> FleetApplyDialog::energisedTargets() const
{
    QList<int> out;
    for (int a : m_targets) {
        const DriveStatus s = m_directory->info(m_connectionId, a).status;
        if (s.enabled || s.running)
            out << a;
    }
    return out;
}

void FleetApplyDialog::updateButtons()
{
    const QList<int> energised = energisedTargets();
    m_confirm->setVisible(!energised.isEmpty());
    if (!energised.isEmpty()) {
        QStringList list;
        for (int a : energised)
            list << QString::number(a);
        m_confirm->setText(tr("Write to the enabled or moving drive(s) %1 anyway: a parameter changed while the "
                              "axis is energised takes effect at once and can make it jerk or move.")
                               .arg(list.join(QLatin1String(", "))));
    }
    bool anything = false;
    for (int a : std::as_const(m_targets))
        anything = anything || (m_states.value(a) == DriveState::Planned && !m_plans.value(a).selected.isEmpty());
    m_apply->setEnabled(isPlanned() && !m_applying && !m_done && anything
                        && (energised.isEmpty() || m_confirm->isChecked()));
}

void FleetApplyDialog::apply()
{
    if (!isPlanned() || m_applying || m_done)
        return;
    if (!energisedTargets().isEmpty() && !m_confirm->isChecked())
        return;
    m_applying = true;
    m_stopping = false;
    updateButtons();
    m_stopAtFirst->setEnabled(false);
    m_message->setText(tr("Writing…"));
    m_queue.clear();
    for (int a : std::as_const(m_targets)) {
        if (m_states.value(a) != DriveState::Planned)
            continue;
        if (m_plans.value(a).selected.isEmpty()) {
            m_states[a] = DriveState::Verified;
            m_reports[a] = m_plans.value(a);
            updateItem(a);
            continue;
        }
        m_queue << a;
    }
    if (m_stopAtFirst->isChecked())
        return startNext();
    const QList<int> all = m_queue;
    m_queue.clear();
    for (int a : all)
        startWrite(a);
    finishIfDone();
}

void FleetApplyDialog::startNext()
{
    if (m_queue.isEmpty() || m_stopping) {
        for (int a : std::as_const(m_queue)) {
            m_states[a] = DriveState::NotAttempted;
            updateItem(a);
        }
        m_queue.clear();
        return finishIfDone();
    }
    startWrite(m_queue.takeFirst());
}

void FleetApplyDialog::startWrite(int address)
{
    m_states[address] = DriveState::Writing;
    updateItem(address);
    auto out = std::make_shared<TransferOutcome>();
    m_directory->hub()->run(m_connectionId, address, TransferOperation::restore(m_file, {}, out),
                            [this, out, address](const DriveResult &r) {
                                // For the commissioning record (ui/report/guijournal.h).
                                const ParameterDictionary &dict = ParameterDictionary::bundled(
                                    m_directory->connectionSettings(m_connectionId).family);
                                if (Error e = VerificationJournal().recordRestore(
                                        GuiJournal::key(m_directory->hub(), m_connectionId, address, r.identity),
                                        out->report, dict, m_sourcePath, BackupFile::checksum(m_file.values())))
                                    m_journalError = e.message;
                                onWritten(address, r.error, out->report);
                            });
}

void FleetApplyDialog::onWritten(int address, const Error &error, const RestoreReport &report)
{
    m_reports[address] = report;
    m_errors[address] = error;
    m_states[address] = error ? DriveState::Failed : DriveState::Verified;
    updateItem(address);
    if (error && m_stopAtFirst->isChecked())
        m_stopping = true;
    if (m_stopAtFirst->isChecked())
        return startNext();
    finishIfDone();
}

void FleetApplyDialog::finishIfDone()
{
    int verified = 0, failed = 0, notAttempted = 0;
    for (int a : std::as_const(m_targets)) {
        switch (m_states.value(a)) {
        case DriveState::Writing: return;
        case DriveState::Verified: ++verified; break;
        case DriveState::NotAttempted: ++notAttempted; break;
        case DriveState::Failed:
        case DriveState::PlanFailed: ++failed; break;
        default: break;
        }
    }
    if (!m_queue.isEmpty())
        return;
    m_applying = false;
    m_done = true;
    m_message->setText(
        (tr("Done: %1 verified, %2 failed, %3 not attempted.").arg(verified).arg(failed).arg(notAttempted)
         + QLatin1Char(' ') + m_journalError)
            .trimmed());
    updateButtons();
    emit applied();
}

QString FleetApplyDialog::message() const
{
    return m_message->text();
}

void FleetApplyDialog::updateItem(int address)
{
    QTreeWidgetItem *item = nullptr;
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i)
        if (m_tree->topLevelItem(i)->data(0, Qt::UserRole).toInt() == address)
            item = m_tree->topLevelItem(i);
    if (!item)
        return;
    const ParameterDictionary &dict = ParameterDictionary::bundled(
        m_file.family().value_or(m_directory->connectionSettings(m_connectionId).family));
    item->setText(0, tr("drive %1").arg(address));
    const RestoreReport &plan = m_plans.value(address);
    const RestoreReport &done = m_reports.value(address);
    QString state;
    switch (m_states.value(address)) {
    case DriveState::Planning: state = tr("reading…"); break;
    case DriveState::Planned:
        state = plan.selected.isEmpty() ? tr("already matches: nothing to write")
                                        : tr("%n parameter(s) will change", nullptr, int(plan.selected.size()));
        break;
    case DriveState::PlanFailed:
        state = tr("not planned: %1 — it will not be written").arg(m_errors.value(address).message);
        break;
    case DriveState::Writing: state = tr("writing…"); break;
    case DriveState::Verified:
        state = tr("verified: %n parameter(s) written and read back", nullptr, int(done.written().size()));
        break;
    case DriveState::Failed: {
        QStringList w, n;
        for (int i : done.written())
            w << dict.label(i);
        for (int i : done.notWritten() + done.indices(RestoreReport::Outcome::Unconfirmed))
            n << dict.label(i);
        state = tr("FAILED: %1 (written: %2; not written or unknown: %3)")
                    .arg(m_errors.value(address).message, w.isEmpty() ? tr("none") : w.join(QLatin1String(", ")),
                         n.isEmpty() ? tr("none") : n.join(QLatin1String(", ")));
        break;
    }
    case DriveState::NotAttempted: state = tr("not attempted (an earlier drive failed)"); break;
    }
    item->setText(1, state);
    // The plan's rows: what changes, and the communication settings left alone.
    qDeleteAll(item->takeChildren());
    for (const DiffEntry &e : plan.selected) {
        auto *child = new QTreeWidgetItem(item);
        child->setText(0, dict.label(e.index));
        child->setText(1,
                       tr("%1 → %2").arg(e.driveValue ? QString::number(*e.driveValue) : QStringLiteral("—"),
                                         e.fileValue ? QString::number(*e.fileValue) : QStringLiteral("—")));
    }
    for (const DiffEntry &e : plan.diff.entries()) {
        if (!e.communication || e.status == DiffStatus::Same || e.status == DiffStatus::OnlyOnDrive)
            continue;
        auto *child = new QTreeWidgetItem(item);
        child->setText(0, dict.label(e.index));
        child->setText(1,
                       tr("left alone: a communication setting (stays %1)")
                           .arg(e.driveValue ? QString::number(*e.driveValue) : QStringLiteral("—")));
    }
    item->setExpanded(true);
}

void FleetApplyDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void FleetApplyDialog::retranslate()
{
    setWindowTitle(tr("Apply to several drives"));
    QStringList list;
    for (int a : std::as_const(m_targets))
        list << QString::number(a);
    m_source->setText(
        tr("From %1 to the drives %2. Communication settings (address, baud rate, station "
           "number) are left alone.")
            .arg(m_sourceName.isEmpty() ? tr("(no source yet)") : m_sourceName, list.join(QLatin1String(", "))));
    m_tree->setHeaderLabels({tr("Drive / parameter"), tr("Plan and result")});
    m_stopAtFirst->setText(tr("Stop at the first failed drive"));
    m_apply->setText(tr("Apply"));
    m_close->setText(tr("Close"));
    for (int a : std::as_const(m_targets))
        updateItem(a);
    updateButtons();
}

} // namespace dd
