#include "ui/panels/tuning/runlist.h"

#include "ui/common/livetext.h"

#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace dd {

RunList::RunList(QWidget *parent)
    : QWidget(parent)
    , m_list(new QListWidget(this))
    , m_open(new QPushButton(this))
    , m_save(new QPushButton(this))
    , m_remove(new QPushButton(this))
    , m_message(new QLabel(this))
{
    m_list->setObjectName(QStringLiteral("runList"));
    m_open->setObjectName(QStringLiteral("openRun"));
    m_save->setObjectName(QStringLiteral("saveRun"));
    m_remove->setObjectName(QStringLiteral("removeRun"));
    m_message->setObjectName(QStringLiteral("runListMessage"));
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_message->hide();
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_open);
    buttons->addWidget(m_save);
    buttons->addWidget(m_remove);
    buttons->addStretch(1);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_list, 1);
    layout->addLayout(buttons);
    layout->addWidget(m_message);

    connect(m_list, &QListWidget::itemChanged, this, [this] {
        if (!m_filling)
            emit overlayChanged();
    });
    connect(m_list, &QListWidget::currentRowChanged, this, [this] {
        updateButtons();
        emit selectionChanged();
    });
    connect(m_open, &QPushButton::clicked, this, &RunList::openInteractive);
    connect(m_save, &QPushButton::clicked, this, &RunList::saveInteractive);
    connect(m_remove, &QPushButton::clicked, this, &RunList::removeSelected);
    retranslate();
    updateButtons();
}

void RunList::addRun(const TuningRun &run)
{
    m_runs.append(run);
    m_filling = true;
    auto *item = new QListWidgetItem(run.label, m_list);
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    item->setCheckState(Qt::Checked);
    item->setToolTip(
        tr("%1 · %2 samples · trigger %3").arg(run.test).arg(run.capture.time.size()).arg(run.capture.triggerSource));
    m_filling = false;
    m_list->setCurrentRow(m_list->count() - 1);
    emit overlayChanged();
}

Error RunList::openFile(const QString &path)
{
    TuningRun run;
    if (Error e = TuningRun::load(path, &run)) {
        const QString why = e.message;
        setMessage([why] { return tr("Not opened: %1").arg(why); }, true);
        return e;
    }
    addRun(run);
    const QString name = QFileInfo(path).fileName();
    setMessage([name] { return tr("Opened %1.").arg(name); }, false);
    emit fileUsed(path);
    return {};
}

Error RunList::saveSelected(const QString &path)
{
    const int i = selectedIndex();
    if (i < 0)
        return {ErrorCode::InvalidArgument, tr("Select a run to save.")};
    if (Error e = m_runs.at(i).save(path)) {
        const QString why = e.message;
        setMessage([why] { return tr("Not saved: %1").arg(why); }, true);
        return e;
    }
    m_runs[i].label = QFileInfo(path).completeBaseName();
    m_list->item(i)->setText(m_runs.at(i).label);
    const QString shown = QDir::toNativeSeparators(path);
    setMessage([shown] { return tr("Saved %1.").arg(shown); }, false);
    emit fileUsed(path);
    emit overlayChanged();
    return {};
}

bool RunList::isOverlaid(int i) const
{
    return i >= 0 && i < m_list->count() && m_list->item(i)->checkState() == Qt::Checked;
}

void RunList::setOverlaid(int i, bool on)
{
    if (i >= 0 && i < m_list->count())
        m_list->item(i)->setCheckState(on ? Qt::Checked : Qt::Unchecked);
}

QList<TuningRun> RunList::overlaidRuns() const
{
    QList<TuningRun> runs;
    for (int i = 0; i < m_runs.size(); ++i)
        if (isOverlaid(i))
            runs << m_runs.at(i);
    return runs;
}

int RunList::selectedIndex() const
{
    return m_list->currentRow();
}

const TuningRun *RunList::selectedRun() const
{
    const int i = selectedIndex();
    return i >= 0 && i < m_runs.size() ? &m_runs.at(i) : nullptr;
}

void RunList::select(int i)
{
    m_list->setCurrentRow(i);
}

QString RunList::message() const
{
    return m_message->text();
}

void RunList::setMessage(std::function<QString()> text, bool problem)
{
    LiveText::set(m_message, std::move(text)); // follows a live language switch
    m_message->setStyleSheet(problem ? QStringLiteral("color: #b00020;") : QString());
    m_message->setVisible(!m_message->text().isEmpty());
}

void RunList::updateButtons()
{
    const bool selected = selectedIndex() >= 0;
    m_save->setEnabled(selected);
    m_remove->setEnabled(selected);
}

void RunList::openInteractive()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Open run"), QString(),
                                                      tr("DriveDesk runs (*.ddrun);;All files (*)"));
    if (!path.isEmpty())
        openFile(path);
}

void RunList::saveInteractive()
{
    const TuningRun *run = selectedRun();
    if (!run)
        return;
    QString path = QFileDialog::getSaveFileName(this, tr("Save run"), run->label + QStringLiteral(".ddrun"),
                                                tr("DriveDesk runs (*.ddrun)"));
    if (path.isEmpty())
        return;
    if (!path.endsWith(QLatin1String(".ddrun")))
        path += QStringLiteral(".ddrun");
    saveSelected(path);
}

void RunList::removeSelected()
{
    const int i = selectedIndex();
    if (i < 0)
        return;
    m_runs.removeAt(i);
    delete m_list->takeItem(i);
    updateButtons();
    emit overlayChanged();
    emit selectionChanged();
}

void RunList::retranslate()
{
    m_open->setText(tr("Open…"));
    m_save->setText(tr("Save…"));
    m_remove->setText(tr("Remove"));
    m_list->setToolTip(tr("Tick the runs to overlay; the selected run is the one saved, analysed and applied."));
}

void RunList::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::LanguageChange)
        retranslate();
}

} // namespace dd
