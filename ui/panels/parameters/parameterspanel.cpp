#include "ui/panels/parameters/parameterspanel.h"

#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "core/drive/drivereply.h"
#include "core/params/parameterdictionary.h"
#include "core/report/verificationjournal.h"
#include "ui/common/displaytext.h"
#include "ui/panels/parameters/parametercontextmenu.h"
#include "ui/panels/parameters/parametertablemodel.h"
#include "ui/panels/parameters/parametervaluedelegate.h"
#include "ui/report/guijournal.h"
#include "ui/workspace/driveparameters.h"

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QSortFilterProxyModel>
#include <QTableView>
#include <QUndoStack>
#include <QVBoxLayout>
#include <algorithm>

namespace dd {

namespace {
// The bundled dictionary of a family as a (non-owning) shared pointer.
std::shared_ptr<const ParameterDictionary> bundledDictionary(Family family)
{
    return std::shared_ptr<const ParameterDictionary>(&ParameterDictionary::bundled(family),
                                                      [](const ParameterDictionary *) {});
}
} // namespace

ParametersPanel::ParametersPanel(const DriveContext &context, QWidget *parent)
    : DrivePanel(context, parent)
{
    m_undo = new QUndoStack(this);
    m_model = new ParameterTableModel(this);
    m_model->setUndoStack(m_undo);
    m_dictionary = bundledDictionary(context.family);
    m_model->setDictionary(m_dictionary, QString());

    m_proxy = new QSortFilterProxyModel(this);
    m_proxy->setSourceModel(m_model);
    m_proxy->setFilterRole(ParameterTableModel::SearchRole);
    m_proxy->setFilterKeyColumn(ParameterTableModel::Index);
    m_proxy->setFilterCaseSensitivity(Qt::CaseInsensitive);

    // Made in this order, which is the Tab order.
    buildSearch();
    buildButtons();
    buildUndoActions();
    buildTable();
    m_progress = createProgressBar(this);
    m_message = createMessageLabel(this, QStringLiteral("parameterMessage"));
    m_genericHint = createReasonLabel(this);
    m_genericHint->setObjectName(QStringLiteral("genericNamesHint"));
    m_genericHint->setTextFormat(Qt::RichText);
    connect(m_genericHint, &QLabel::linkActivated, this, &ParametersPanel::chooseDictionary);
    connectMessages();
    connectSharedValues();
    layOut();

    retranslate();
    m_view->resizeColumnsToContents();
}

void ParametersPanel::buildSearch()
{
    m_search = new QLineEdit(this);
    m_search->setObjectName(QStringLiteral("parameterSearch"));
    m_search->setClearButtonEnabled(true);
    connect(m_search, &QLineEdit::textChanged, this, [this](const QString &text) {
        m_proxy->setFilterFixedString(text.trimmed());
        updateCount();
    });
    m_count = new QLabel(this);
}

void ParametersPanel::buildButtons()
{
    m_readAll = new QPushButton(this);
    m_readAll->setObjectName(QStringLiteral("readAllButton"));
    m_writeSelected = new QPushButton(this);
    m_writeSelected->setObjectName(QStringLiteral("writeSelectedButton"));
    m_writeChanged = new QPushButton(this);
    m_writeChanged->setObjectName(QStringLiteral("writeChangedButton"));
    m_undoButton = new QPushButton(this);
    m_undoButton->setObjectName(QStringLiteral("undoButton"));
    m_redoButton = new QPushButton(this);
    m_redoButton->setObjectName(QStringLiteral("redoButton"));
    connect(m_readAll, &QPushButton::clicked, this, &ParametersPanel::readAll);
    connect(m_writeSelected, &QPushButton::clicked, this, &ParametersPanel::writeSelected);
    connect(m_writeChanged, &QPushButton::clicked, this, &ParametersPanel::writeAllChanged);
    connect(m_undoButton, &QPushButton::clicked, m_undo, &QUndoStack::undo);
    connect(m_redoButton, &QPushButton::clicked, m_undo, &QUndoStack::redo);
}

void ParametersPanel::buildUndoActions()
{
    // Ctrl+Z / Ctrl+Shift+Z anywhere in the tab (the search box keeps its own).
    m_undoAction = new QAction(this);
    m_undoAction->setShortcut(QKeySequence::Undo);
    m_undoAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    connect(m_undoAction, &QAction::triggered, m_undo, &QUndoStack::undo);
    m_redoAction = new QAction(this);
    m_redoAction->setShortcut(QKeySequence::Redo);
    m_redoAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    connect(m_redoAction, &QAction::triggered, m_undo, &QUndoStack::redo);
    addAction(m_undoAction);
    addAction(m_redoAction);
    connect(m_undo, &QUndoStack::indexChanged, this, &ParametersPanel::updateActions);
}

void ParametersPanel::buildTable()
{
    m_view = new QTableView(this);
    m_view->setObjectName(QStringLiteral("parameterTable"));
    m_view->setModel(m_proxy);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                            | QAbstractItemView::AnyKeyPressed);
    m_view->setAlternatingRowColors(true);
    m_view->verticalHeader()->hide();
    m_view->verticalHeader()->setDefaultSectionSize(m_view->fontMetrics().height() + 8);
    m_view->horizontalHeader()->setSectionResizeMode(ParameterTableModel::Mark, QHeaderView::ResizeToContents);
    m_view->horizontalHeader()->setSectionResizeMode(ParameterTableModel::Name, QHeaderView::Stretch);
    m_delegate = new ParameterValueDelegate(m_model, this);
    m_view->setItemDelegateForColumn(ParameterTableModel::Value, m_delegate);
    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this, &ParametersPanel::updateActions);
    // Ctrl+C on the table: the selected rows, as the context menu's Copy.
    auto *copy = new QAction(m_view);
    copy->setShortcut(QKeySequence::Copy);
    copy->setShortcutContext(Qt::WidgetShortcut);
    connect(copy, &QAction::triggered, this, [this] {
        QApplication::clipboard()->setText(ParameterContextMenu::copyText(m_model, selectedParameters()));
    });
    m_view->addAction(copy);
    m_view->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(m_view, &QWidget::customContextMenuRequested, this, [this](const QPoint &pos) {
        const QModelIndex at = m_proxy->mapToSource(m_view->indexAt(pos));
        if (!at.isValid())
            return;
        ParameterContextMenu *menu = contextMenuFor(m_model->parameterAt(at.row()));
        menu->setAttribute(Qt::WA_DeleteOnClose);
        menu->popup(m_view->viewport()->mapToGlobal(pos));
    });
}

ParameterContextMenu *ParametersPanel::contextMenuFor(int parameterIndex)
{
    const bool canWrite = !m_busy && context().can(Capability::WriteParameters);
    QPointer<ParametersPanel> self(this);
    return new ParameterContextMenu(
        m_model, parameterIndex, selectedParameters(),
        [self](int p) {
            if (self)
                self->write({p}, false);
        },
        canWrite, this);
}

void ParametersPanel::connectMessages()
{
    connect(m_delegate, &ParameterValueDelegate::problemChanged, this, [this](const QString &reason) {
        if (reason.isEmpty())
            setMessage(QString(), MessageKind::Info);
        else
            setMessage(reason, MessageKind::Problem);
    });
    connect(m_delegate, &ParameterValueDelegate::valueRefused, this, [this](const QString &reason) {
        setMessage(tr("Not accepted: %1 Nothing was sent to the drive.").arg(DisplayText::sentence(reason)),
                   MessageKind::Problem);
    });
    connect(m_model, &ParameterTableModel::editRefused, this, [this](int, const Error &reason) {
        setMessage(tr("Not accepted: %1 Nothing was sent to the drive.").arg(DisplayText::sentence(reason.message)),
                   MessageKind::Problem);
    });
    connect(m_model, &ParameterTableModel::editsChanged, this, &ParametersPanel::updateActions);
}

void ParametersPanel::connectSharedValues()
{
    // The drive's values are shared with its other panels: whoever reads or writes, every
    // view follows (a restore, an EE operation, this tab).
    DriveParameters *shared = parameters();
    connect(shared, &DriveParameters::valuesRead, this,
            [this](const QMap<int, qint64> &values, ValueSource source) { m_model->setDriveValues(values, source); });
    connect(shared, &DriveParameters::writesReported, this,
            [this](const QList<ParameterWriteResult> &results, QObject *origin) {
                if (origin == this)
                    return; // onWritten() has shown them, with their write states
                QMap<int, qint64> read;
                QMap<int, qint64> lastWritten;
                for (const ParameterWriteResult &r : results) {
                    if (r.outcome == WriteOutcome::Verified || r.outcome == WriteOutcome::Mismatch)
                        read.insert(r.index, r.readBack);
                    else if (r.outcome == WriteOutcome::WriteOnly)
                        lastWritten.insert(r.index, r.requested);
                }
                m_model->setDriveValues(read);
                m_model->setDriveValues(lastWritten, ValueSource::LastWritten);
                if (!read.isEmpty() || !lastWritten.isEmpty())
                    setMessage(tr("%n value(s) changed on the drive by another tab; shown here.", nullptr,
                                  int(read.size() + lastWritten.size())),
                               MessageKind::Info);
            });
    connect(shared, &DriveParameters::valuesReplaced, this, [this] {
        // Every value may differ now: read them again (at once when shown, else when shown).
        m_everRead = false;
        setMessage(tr("The drive's values were replaced (EEPROM operation): reading them again."), MessageKind::Info);
        maybeReadFirstTime();
    });
    connect(shared, &DriveParameters::unsavedChanged, this, [this] { m_model->setUnsaved(parameters()->unsaved()); });
}

void ParametersPanel::layOut()
{
    auto *top = new QHBoxLayout;
    top->addWidget(m_search, 2);
    top->addWidget(m_count);
    top->addStretch(1);
    top->addWidget(m_undoButton);
    top->addWidget(m_redoButton);
    auto *bottom = new QHBoxLayout;
    bottom->addWidget(m_readAll);
    bottom->addWidget(m_writeSelected);
    bottom->addWidget(m_writeChanged);
    bottom->addWidget(m_progress);
    bottom->addWidget(m_message, 1);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(m_genericHint);
    layout->addWidget(m_view, 1);
    layout->addLayout(bottom);
}

ParametersPanel::~ParametersPanel()
{
    // The undo stack is a child: QWidget deletes it after this class is gone, and its
    // destructor emits indexChanged — which must not reach a half-destroyed panel (UBSan:
    // invalid downcast in the slot call).
    m_undo->disconnect(this);
}

QString ParametersPanel::title() const
{
    return tr("Parameters");
}

QString ParametersPanel::message() const
{
    return m_message->text();
}

void ParametersPanel::readAll()
{
    if (m_busy || !context().isValid())
        return;
    // Write-only parameters are asked for too: the drive skips them, but may report what
    // it last wrote to them (reply info "lastWritten").
    const QList<int> indices = m_model->parameterIndices();
    if (m_model->readableIndices().isEmpty()) {
        setMessage(tr("This drive has no parameter that can be read."), MessageKind::Info);
        return;
    }
    setBusy(true, tr("Reading %n parameter(s)…", nullptr, int(m_model->readableIndices().size())));
    auto dictionary = std::make_shared<std::shared_ptr<const ParameterDictionary>>();
    QPointer<ParametersPanel> self(this);
    context().hub->run(
        context().connectionId, context().address,
        [indices, dictionary](Drive &d) {
            *dictionary = d.dictionary(); // a user's dictionary, when one is set
            return d.readParameters(indices);
        },
        [self, dictionary](const DriveResult &r) {
            if (self)
                self->onRead(r, *dictionary);
        },
        progressOn(m_progress));
}

void ParametersPanel::onRead(const DriveResult &result, std::shared_ptr<const ParameterDictionary> dictionary)
{
    setBusy(false);
    if (dictionary && dictionary != m_dictionary) {
        m_dictionary = dictionary;
        m_model->setDictionary(m_dictionary, m_modelName);
        updateGenericHint();
    }
    // Through the shared values: every view of this drive follows (connectSharedValues()).
    parameters()->reportRead(result.parameters);
    QMap<int, qint64> lastWritten;
    const QVariantMap reported = result.info.value(QStringLiteral("lastWritten")).toMap();
    for (auto it = reported.begin(); it != reported.end(); ++it)
        lastWritten.insert(it.key().toInt(), it.value().toLongLong());
    parameters()->reportRead(lastWritten, ValueSource::LastWritten);
    // Sized to the values once; afterwards reads and writes keep the user's column layout.
    if (!m_columnsSized && !result.parameters.isEmpty()) {
        m_columnsSized = true;
        m_view->resizeColumnsToContents();
    }
    if (!reportResult(result)) {
        setMessage(tr("Reading failed after %n parameter(s): %1", nullptr, int(result.parameters.size()))
                       .arg(result.error.message),
                   MessageKind::Problem);
        emit operationFinished(false);
        return;
    }
    m_everRead = true;
    const int count = int(result.parameters.size());
    const int pending = int(m_model->changedIndices().size());
    showMessage(
        m_message,
        [count, pending] {
            QString text = tr("Read %n parameter(s) from the drive.", nullptr, count);
            if (pending > 0)
                text += QLatin1Char(' ') + tr("%n edited value(s) not yet written.", nullptr, pending);
            return text;
        },
        MessageKind::Success);
    emit operationFinished(true);
}

bool ParametersPanel::namesAreGeneric() const
{
    const ParameterDictionary *d = m_model->dictionary();
    if (!d || d->isEmpty())
        return false;
    // The bundled dictionaries name what the protocol documents name; the rest read
    // "Parameter N" / "Parameter PAN".
    int generic = 0;
    for (const ParameterInfo &p : d->parameters())
        generic += p.name.english().startsWith(QLatin1String("Parameter ")) ? 1 : 0;
    return generic * 2 > d->size();
}

void ParametersPanel::updateGenericHint()
{
    m_genericHint->setText(tr("Most names here are generic: the protocol document does not name these "
                              "parameters. Load your drive's dictionary: File → <a href=\"load\">Load "
                              "dictionary…</a>"));
    m_genericHint->setVisible(namesAreGeneric());
}

Error ParametersPanel::loadDictionary(const QString &path)
{
    auto dictionary = std::make_shared<ParameterDictionary>();
    if (Error e = dictionary->loadFromFile(path, context().family)) {
        const QString why = e.message;
        showMessage(
            m_message,
            [why] { return tr("Dictionary not loaded: %1 The table is unchanged.").arg(DisplayText::sentence(why)); },
            MessageKind::Problem);
        return e;
    }
    m_dictionary = dictionary;
    m_model->setDictionary(m_dictionary, m_modelName);
    updateGenericHint();
    updateCount();
    const int count = dictionary->size();
    const QString shown = QDir::toNativeSeparators(path);
    showMessage(
        m_message,
        [count, shown] {
            return tr("Loaded the dictionary %1: %n parameter(s). Read all to see their values.", nullptr, count)
                .arg(shown);
        },
        MessageKind::Success);
    emit fileUsed(path);
    // The drive validates writes with it too (until the connection closes).
    if (context().isValid())
        context().hub->run(context().connectionId, context().address, [dictionary](Drive &d) {
            d.setDictionary(dictionary);
            auto *reply = new DriveReply(&d);
            reply->finish();
            return reply;
        });
    return Error::none();
}

void ParametersPanel::chooseDictionary()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Load a parameter dictionary"), QString(),
                                                      tr("DriveDesk dictionaries (*.json)"));
    if (!path.isEmpty())
        loadDictionary(path);
}

void ParametersPanel::writeSelected()
{
    write(selectedParameters(), true);
}

void ParametersPanel::writeAllChanged()
{
    write(m_model->changedIndices(), false);
}

void ParametersPanel::write(const QList<int> &indices, bool onlySelected)
{
    if (m_busy || !context().isValid())
        return;
    QList<ParameterWrite> writes;
    QList<int> requested;
    for (int p : indices) {
        if (!m_model->isChanged(p))
            continue;
        writes.append({p, *m_model->editedValue(p)});
        requested << p;
    }
    if (writes.isEmpty()) {
        setMessage(onlySelected ? tr("Nothing to write: no selected row has an edited value.")
                                : tr("Nothing to write: no value was edited."),
                   MessageKind::Info);
        return;
    }
    // Every value is checked again before anything is sent (the drive checks them too).
    for (const ParameterWrite &w : std::as_const(writes)) {
        if (Error e = m_model->dictionary()->validateWrite(w.index, w.value)) {
            setMessage(tr("Not written: %1 Nothing was sent to the drive.").arg(DisplayText::sentence(e.message)),
                       MessageKind::Problem);
            return;
        }
    }
    if (!confirmCommunicationWrites(requested)) {
        setMessage(tr("Not written: cancelled."), MessageKind::Info);
        return;
    }
    setBusy(true, tr("Writing %n parameter(s)…", nullptr, int(writes.size())));
    QPointer<ParametersPanel> self(this);
    context().hub->run(
        context().connectionId, context().address, [writes](Drive &d) { return d.writeParameters(writes); },
        [self, requested](const DriveResult &r) {
            if (self)
                self->onWritten(r, requested);
        },
        progressOn(m_progress));
}

bool ParametersPanel::confirmCommunicationWrites(const QList<int> &indices)
{
    QStringList names;
    for (int p : indices)
        if (const ParameterInfo *info = m_model->info(p); info && info->communication)
            names << m_model->dictionary()->label(p);
    if (names.isEmpty())
        return true;
    QMessageBox box(QMessageBox::Warning, tr("Change communication settings?"),
                    tr("%1 changes how the drive communicates (address, baud rate or framing). After "
                       "the change DriveDesk may no longer reach the drive with the current connection "
                       "settings: connect again with the new ones.\n\nWrite anyway?")
                        .arg(names.join(QLatin1String(", "))),
                    QMessageBox::Yes | QMessageBox::Cancel, this);
    box.setObjectName(QStringLiteral("communicationWriteConfirmation"));
    box.setDefaultButton(QMessageBox::Cancel);
    return box.exec() == QMessageBox::Yes;
}

void ParametersPanel::onWritten(const DriveResult &result, const QList<int> &requested)
{
    setBusy(false);
    m_model->applyWriteResults(result.writes, requested);
    parameters()->reportWrites(result.writes, this);
    Error journal; // for the commissioning record (ui/report/guijournal.h)
    if (!result.writes.isEmpty())
        journal = GuiJournal::verification(context(), result.identity,
                                           VerificationJournal::fromWrites(result.writes, *m_model->dictionary()));
    int verified = 0;
    int writtenOnly = 0;
    int failed = 0;
    for (int p : requested) {
        switch (m_model->writeState(p)) {
        case ParameterTableModel::WriteState::Verified: ++verified; break;
        case ParameterTableModel::WriteState::WrittenOnly: ++writtenOnly; break;
        default: ++failed; break;
        }
    }
    const bool ok = result.ok() && failed == 0;
    QString error = result.ok() ? QString() : result.error.message;
    if (journal)
        error = (error + QLatin1Char(' ') + journal.message).trimmed();
    showMessage(
        m_message,
        [verified, writtenOnly, failed, error] {
            QStringList parts;
            parts << tr("%n written and verified", nullptr, verified);
            if (writtenOnly)
                parts << tr("%n written (write-only, cannot be read back)", nullptr, writtenOnly);
            if (failed)
                parts << tr("%n failed or not written", nullptr, failed);
            QString text = parts.join(QLatin1String(", ")) + QLatin1Char('.');
            if (!error.isEmpty())
                text += QLatin1Char(' ') + error;
            return text;
        },
        ok ? MessageKind::Success : MessageKind::Problem);
    reportResult(result);
    emit operationFinished(ok);
}

void ParametersPanel::setBusy(bool busy, const QString &what)
{
    m_busy = busy;
    m_progress->setVisible(busy);
    m_progress->setRange(0, 0); // busy until the first progress report
    // No edits while the drive is being read or written: a result must not overwrite them.
    m_view->setEditTriggers(busy ? QAbstractItemView::NoEditTriggers
                                 : QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                                    | QAbstractItemView::AnyKeyPressed);
    if (busy)
        setMessage(what, MessageKind::Info);
    updateActions();
}

void ParametersPanel::setMessage(const QString &text, MessageKind kind)
{
    showMessage(m_message, text, kind);
}

void ParametersPanel::updateActions()
{
    const bool canRead = context().can(Capability::ReadParameters);
    const bool canWrite = context().can(Capability::WriteParameters);
    const bool changed = !m_model->changedIndices().isEmpty();
    bool selectedChanged = false;
    for (int p : selectedParameters())
        selectedChanged = selectedChanged || m_model->isChanged(p);
    m_readAll->setEnabled(!m_busy && canRead);
    m_writeSelected->setEnabled(!m_busy && canWrite && selectedChanged);
    m_writeChanged->setEnabled(!m_busy && canWrite && changed);
    m_readAll->setToolTip(canRead ? tr("Read every parameter from the drive")
                                  : driveInfo().reason(Capability::ReadParameters));
    const QString writeReason = canWrite ? QString() : driveInfo().reason(Capability::WriteParameters);
    m_writeSelected->setToolTip(canWrite ? tr("Write the edited values of the selected rows; the drive reads each back")
                                         : writeReason);
    m_writeChanged->setToolTip(canWrite ? tr("Write every edited value; the drive reads each back") : writeReason);
    m_undoButton->setEnabled(!m_busy && m_undo->canUndo());
    m_redoButton->setEnabled(!m_busy && m_undo->canRedo());
    m_undoAction->setEnabled(m_undoButton->isEnabled());
    m_redoAction->setEnabled(m_redoButton->isEnabled());
    m_undoButton->setToolTip(m_undo->canUndo() ? tr("Undo: %1").arg(m_undo->undoText()) : QString());
    m_redoButton->setToolTip(m_undo->canRedo() ? tr("Redo: %1").arg(m_undo->redoText()) : QString());
}

void ParametersPanel::updateCount()
{
    m_count->setText(tr("%1 of %2").arg(m_proxy->rowCount()).arg(m_model->rowCount()));
}

QList<int> ParametersPanel::selectedParameters() const
{
    QList<int> out;
    const QModelIndexList rows = m_view->selectionModel()->selectedRows();
    for (const QModelIndex &i : rows)
        out << i.data(ParameterTableModel::ParameterIndexRole).toInt();
    std::sort(out.begin(), out.end());
    return out;
}

void ParametersPanel::activeChanged(bool active)
{
    if (active)
        maybeReadFirstTime();
}

void ParametersPanel::maybeReadFirstTime()
{
    // The first time the tab is shown, fill it (once the drive's capabilities are known).
    if (isActive() && !m_everRead && !m_busy && context().can(Capability::ReadParameters))
        readAll();
}

void ParametersPanel::driveInfoChanged(const DriveInfo &info)
{
    if (info.identity.model != m_modelName) {
        m_modelName = info.identity.model;
        m_model->setDictionary(m_dictionary, m_modelName);
        updateCount();
    }
    updateActions();
    maybeReadFirstTime();
}

void ParametersPanel::retranslate()
{
    m_search->setPlaceholderText(tr("Search by index, key or name"));
    m_readAll->setText(tr("Read all"));
    m_writeSelected->setText(tr("Write selected"));
    m_writeChanged->setText(tr("Write all changed"));
    m_undoButton->setText(tr("Undo"));
    m_redoButton->setText(tr("Redo"));
    m_model->retranslate();
    updateCount();
    updateActions();
    updateGenericHint();
}

bool ParametersPanel::openFile(const QString &path)
{
    // A parameter dictionary picked from File → Recent files (other JSON: other tabs').
    QFile file(path);
    if (!path.endsWith(QLatin1String(".json"), Qt::CaseInsensitive) || !file.open(QIODevice::ReadOnly))
        return false;
    if (!file.read(4096).contains("\"drivedesk-dictionary\""))
        return false;
    loadDictionary(path);
    return true;
}

} // namespace dd
