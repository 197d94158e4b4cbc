#include "ui/panels/tuning/tuningparameterseditor.h"

#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "core/drive/driveresult.h"
#include "core/params/parameterdictionary.h"
#include "core/report/verificationjournal.h"
#include "core/tuning/runparameterapply.h"
#include "ui/common/displaytext.h"
#include "ui/common/livetext.h"
#include "ui/report/guijournal.h"
#include "ui/workspace/driveparameters.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPointer>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace dd {

TuningParametersEditor::TuningParametersEditor(const DriveContext &context, QWidget *parent)
    : QWidget(parent)
    , m_context(context)
    , m_table(new QTableWidget(this))
    , m_read(new QPushButton(this))
    , m_write(new QPushButton(this))
    , m_note(new QLabel(this))
    , m_message(new QLabel(this))
{
    m_table->setObjectName(QStringLiteral("tuningParameters"));
    m_read->setObjectName(QStringLiteral("readTuning"));
    m_write->setObjectName(QStringLiteral("writeTuning"));
    m_note->setObjectName(QStringLiteral("tuningSourceNote"));
    m_message->setObjectName(QStringLiteral("tuningMessage"));
    m_table->setColumnCount(2);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_table->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    for (QLabel *l : {m_note, m_message}) {
        l->setWordWrap(true);
        l->setTextInteractionFlags(Qt::TextSelectableByMouse);
        l->hide();
    }
    m_note->setEnabled(false);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_read);
    buttons->addWidget(m_write);
    buttons->addStretch(1);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_table, 1);
    layout->addLayout(buttons);
    layout->addWidget(m_note);
    layout->addWidget(m_message);

    connect(m_read, &QPushButton::clicked, this, &TuningParametersEditor::readValues);
    connect(m_write, &QPushButton::clicked, this, &TuningParametersEditor::writeEdited);
    connect(m_table, &QTableWidget::itemChanged, this, &TuningParametersEditor::onItemChanged);
    if (DriveParameters *shared = m_context.parameters) {
        connect(shared, &DriveParameters::valuesRead, this, &TuningParametersEditor::refreshValues);
        connect(shared, &DriveParameters::writesReported, this, &TuningParametersEditor::refreshValues);
        connect(shared, &DriveParameters::valuesReplaced, this, &TuningParametersEditor::readValues);
    }
    retranslate();
    setBusy(false);
}

void TuningParametersEditor::setDictionary(std::shared_ptr<const ParameterDictionary> dictionary)
{
    m_dictionary = std::move(dictionary);
    m_entries.clear();
    m_simulatorFallback = false;
    m_names = m_dictionary.get();
    if (m_dictionary) {
        m_entries = entriesFor(*m_dictionary, m_context.family, &m_simulatorFallback);
        if (m_simulatorFallback)
            m_names = &ParameterDictionary::bundledSimulator(m_context.family);
    }
    m_edited.clear();
    rebuildRows();
    retranslate();
}

QVector<TuningEntry> TuningParametersEditor::entriesFor(const ParameterDictionary &dictionary, Family family,
                                                        bool *simulator)
{
    if (simulator)
        *simulator = false;
    if (!dictionary.tuning().isEmpty())
        return dictionary.tuning();
    QVector<TuningEntry> entries;
    for (const TuningEntry &e : ParameterDictionary::bundledSimulator(family).tuning())
        if (dictionary.byIndex(e.index))
            entries.append(e);
    if (simulator)
        *simulator = !entries.isEmpty();
    return entries;
}

QString TuningParametersEditor::keyOf(int index) const
{
    const ParameterInfo *p = m_names ? m_names->byIndex(index) : nullptr;
    return p ? p->key : QStringLiteral("P%1").arg(index);
}

std::optional<qint64> TuningParametersEditor::knownValue(int index) const
{
    if (!m_context.parameters)
        return std::nullopt;
    const ParameterValue v = m_context.parameters->value(index);
    return v.isKnown() ? std::optional<qint64>(v.value) : std::nullopt;
}

Error TuningParametersEditor::setEdited(int index, qint64 value)
{
    if (!m_dictionary)
        return {ErrorCode::InvalidArgument, tr("The drive's dictionary is not known yet.")};
    if (Error e = m_dictionary->validateWrite(index, value))
        return e;
    m_edited.insert(index, value);
    refreshValues();
    setBusy(m_busy);
    return {};
}

void TuningParametersEditor::rebuildRows()
{
    m_filling = true;
    m_table->setRowCount(int(m_entries.size()));
    for (int r = 0; r < m_entries.size(); ++r) {
        const int index = m_entries.at(r).index;
        auto *name = new QTableWidgetItem;
        name->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
        name->setData(Qt::UserRole, index);
        m_table->setItem(r, 0, name);
        auto *value = new QTableWidgetItem;
        value->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable);
        value->setData(Qt::UserRole, index);
        value->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        m_table->setItem(r, 1, value);
    }
    m_filling = false;
    refreshValues();
}

void TuningParametersEditor::refreshValues()
{
    m_filling = true;
    for (int r = 0; r < m_entries.size(); ++r) {
        const int index = m_entries.at(r).index;
        QTableWidgetItem *name = m_table->item(r, 0);
        QTableWidgetItem *value = m_table->item(r, 1);
        if (!name || !value)
            continue;
        const ParameterInfo *p = m_names ? m_names->byIndex(index) : nullptr;
        const QString unit = p ? DisplayText::unit(p->unit) : QString();
        name->setText(m_names ? m_names->label(index) : keyOf(index));
        name->setToolTip(p ? p->description.text(QLocale()) : QString());
        QFont f = value->font();
        if (m_edited.contains(index)) {
            value->setText(QString::number(m_edited.value(index)));
            f.setBold(true);
            value->setToolTip(tr("Edited, not yet written"));
        } else if (const auto v = knownValue(index)) {
            value->setText(unit.isEmpty() ? QString::number(*v) : QStringLiteral("%1 %2").arg(*v).arg(unit));
            f.setBold(false);
            value->setToolTip(QString());
        } else {
            value->setText(tr("not read"));
            f.setBold(false);
            value->setToolTip(QString());
        }
        value->setFont(f);
    }
    m_filling = false;
}

void TuningParametersEditor::onItemChanged(QTableWidgetItem *item)
{
    if (m_filling || item->column() != 1)
        return;
    const int index = item->data(Qt::UserRole).toInt();
    QString text = item->text().trimmed();
    const ParameterInfo *p = m_names ? m_names->byIndex(index) : nullptr;
    const QString unit = p ? DisplayText::unit(p->unit) : QString();
    if (!unit.isEmpty() && text.endsWith(unit))
        text = text.chopped(unit.size()).trimmed();
    bool ok = false;
    const qint64 value = text.toLongLong(&ok);
    Error e = ok ? setEdited(index, value)
                 : Error{ErrorCode::InvalidArgument, tr("\"%1\" is not a whole number.").arg(item->text())};
    if (e) {
        const QString why = e.message;
        setMessage([why] { return tr("Not taken: %1").arg(why); }, true);
        refreshValues();
    }
}

void TuningParametersEditor::readValues()
{
    if (m_busy || !m_context.isValid() || m_entries.isEmpty())
        return;
    QList<int> indices;
    for (const TuningEntry &e : std::as_const(m_entries))
        indices << e.index;
    setBusy(true);
    QPointer<TuningParametersEditor> self(this);
    m_context.hub->run(
        m_context.connectionId, m_context.address, [indices](Drive &d) { return d.readParameters(indices); },
        [self](const DriveResult &r) {
            if (!self)
                return;
            self->setBusy(false);
            if (self->m_context.parameters)
                self->m_context.parameters->reportRead(r.parameters);
            if (!r.ok()) {
                const QString why = r.error.message;
                self->setMessage([why] { return tr("Reading the tuning parameters failed: %1").arg(why); }, true);
                emit self->errorOccurred(r.error);
            }
        });
}

void TuningParametersEditor::writeEdited()
{
    if (m_busy || !m_context.isValid() || m_edited.isEmpty() || !m_dictionary)
        return;
    QList<ParameterWrite> writes;
    for (auto it = m_edited.cbegin(); it != m_edited.cend(); ++it) {
        if (Error e = m_dictionary->validateWrite(it.key(), it.value())) {
            const QString why = e.message;
            setMessage([why] { return tr("Not written: %1 Nothing was sent.").arg(why); }, true);
            return;
        }
        writes.append({it.key(), it.value()});
    }
    writeValues(writes, QString(), 0);
}

void TuningParametersEditor::applyRun(const TuningRun &run, const DriveIdentity &drive)
{
    if (m_busy || !m_context.isValid() || !m_dictionary)
        return;
    Error e = RunParameterApply::check(run, m_context.family, *m_dictionary, &m_entries);
    if (!e)
        e = RunParameterApply::checkDrive(run, drive);
    if (e) {
        const QString why = e.message;
        setMessage([why] { return tr("Not applied: %1").arg(why); }, true);
        return;
    }
    applySnapshot(run.tuning, run.label);
}

void TuningParametersEditor::applySnapshot(const QList<TuningSnapshotEntry> &snapshot, const QString &runLabel)
{
    if (m_busy || !m_context.isValid() || !m_dictionary || snapshot.isEmpty())
        return;
    QList<int> indices;
    for (const TuningSnapshotEntry &e : snapshot) {
        if (Error err = m_dictionary->validateWrite(e.index, e.value)) {
            const QString why = err.message;
            setMessage([why] { return tr("Not applied: %1 Nothing was sent.").arg(why); }, true);
            return;
        }
        indices << e.index;
    }
    setBusy(true);
    QPointer<TuningParametersEditor> self(this);
    m_context.hub->run(
        m_context.connectionId, m_context.address, [indices](Drive &d) { return d.readParameters(indices); },
        [self, snapshot, runLabel](const DriveResult &r) {
            if (!self)
                return;
            self->setBusy(false);
            if (self->m_context.parameters)
                self->m_context.parameters->reportRead(r.parameters);
            if (!r.ok()) {
                const QString why = r.error.message;
                self->setMessage([why] { return tr("Not applied: reading the drive failed: %1").arg(why); }, true);
                emit self->errorOccurred(r.error);
                return;
            }
            QList<ParameterWrite> writes;
            int equal = 0;
            for (const TuningSnapshotEntry &e : snapshot) {
                if (r.parameters.contains(e.index) && r.parameters.value(e.index) == e.value)
                    ++equal;
                else
                    writes.append({e.index, e.value});
            }
            for (const ParameterWrite &w : std::as_const(writes))
                self->m_edited.remove(w.index);
            if (writes.isEmpty()) {
                self->refreshValues();
                self->setMessage(
                    [runLabel, equal] {
                        return tr("%1: the drive already has these %n value(s); nothing written.", nullptr, equal)
                            .arg(runLabel);
                    },
                    false);
                return;
            }
            self->writeValues(writes, runLabel, equal);
        });
}

void TuningParametersEditor::writeValues(const QList<ParameterWrite> &writes, const QString &runLabel, int alreadyEqual)
{
    setBusy(true);
    QPointer<TuningParametersEditor> self(this);
    m_context.hub->run(
        m_context.connectionId, m_context.address, [writes](Drive &d) { return d.writeParameters(writes); },
        [self, runLabel, alreadyEqual](const DriveResult &r) {
            if (!self)
                return;
            int verified = 0;
            QStringList failed;
            for (const ParameterWriteResult &w : r.writes) {
                if (w.verified) {
                    ++verified;
                    self->m_edited.remove(w.index);
                } else {
                    failed << QStringLiteral("%1: %2").arg(self->keyOf(w.index), w.error);
                }
            }
            self->setBusy(false);
            if (self->m_context.parameters)
                self->m_context.parameters->reportWrites(r.writes, self);
            Error journal; // gain edits and applied runs, for the commissioning record
            if (!r.writes.isEmpty())
                journal = GuiJournal::verification(
                    self->m_context, r.identity,
                    VerificationJournal::fromWrites(
                        r.writes,
                        self->m_names ? *self->m_names : ParameterDictionary::bundled(self->m_context.family)));
            self->refreshValues();
            QString error = r.ok() ? QString() : r.error.message;
            if (journal)
                error = (error + QLatin1Char(' ') + journal.message).trimmed();
            const bool problem = !failed.isEmpty() || !error.isEmpty();
            self->setMessage(
                [verified, failed, error, runLabel, alreadyEqual] {
                    QString text = tr("%n written and read back.", nullptr, verified);
                    if (!runLabel.isEmpty())
                        text = tr("%1 applied:", nullptr).arg(runLabel) + QLatin1Char(' ') + text + QLatin1Char(' ')
                            + tr("%n already equal.", nullptr, alreadyEqual);
                    if (!failed.isEmpty())
                        text += QLatin1Char(' ') + tr("Not verified: %1.").arg(failed.join(QStringLiteral("; ")));
                    if (!error.isEmpty())
                        text += QLatin1Char(' ') + error;
                    return text;
                },
                problem);
            if (!r.ok())
                emit self->errorOccurred(r.error);
        });
}

QString TuningParametersEditor::message() const
{
    return m_message->text();
}

void TuningParametersEditor::setBusy(bool busy)
{
    const bool changed = busy != m_busy;
    m_busy = busy;
    m_read->setEnabled(!busy && !m_entries.isEmpty() && m_context.isValid());
    m_write->setEnabled(!busy && !m_edited.isEmpty() && m_context.isValid());
    if (changed)
        emit busyChanged(busy);
}

void TuningParametersEditor::setMessage(std::function<QString()> text, bool problem)
{
    LiveText::set(m_message, std::move(text));
    m_message->setStyleSheet(problem ? QStringLiteral("color: #b00020;") : QString());
    m_message->show();
}

void TuningParametersEditor::retranslate()
{
    m_table->setHorizontalHeaderLabels({tr("Parameter"), tr("Value")});
    m_read->setText(tr("Read"));
    m_write->setText(tr("Write"));
    m_write->setToolTip(tr("Write the edited values and read them back."));
    if (!m_dictionary) {
        m_note->setText(tr("Reading the drive's dictionary…"));
    } else if (m_entries.isEmpty()) {
        m_note->setText(tr("This drive's dictionary names no tuning parameters. A dictionary with a \"tuning\" "
                           "group names them (docs/dictionaries.md)."));
    } else if (m_simulatorFallback) {
        m_note->setText(tr("The drive's dictionary names no tuning parameters: shown are the DriveDesk "
                           "simulator's loop gains (its own model). On a real drive these parameters may mean "
                           "something else."));
    } else {
        m_note->clear();
    }
    m_note->setVisible(!m_note->text().isEmpty());
    refreshValues();
    setBusy(m_busy);
}

void TuningParametersEditor::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::LanguageChange)
        retranslate();
}

} // namespace dd
