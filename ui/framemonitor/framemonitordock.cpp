#include "ui/framemonitor/framemonitordock.h"

#include "core/link/trafficlog.h"
#include "ui/framemonitor/framemonitorfilter.h"
#include "ui/framemonitor/framemonitormodel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QStyle>
#include <QToolButton>
#include <QTreeView>
#include <QVBoxLayout>

namespace dd {

namespace {
QToolButton *toolButton(QWidget *parent, const QString &objectName, const QIcon &icon)
{
    auto *b = new QToolButton(parent);
    b->setObjectName(objectName);
    b->setIcon(icon);
    b->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    return b;
}
} // namespace

FrameMonitorDock::FrameMonitorDock(DriveHub *hub, QWidget *parent)
    : QDockWidget(parent)
{
    setObjectName(QStringLiteral("frameMonitorDock"));
    setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable | QDockWidget::DockWidgetClosable);

    m_model = new FrameMonitorModel(this);
    m_model->setHub(hub);
    m_filter = new FrameMonitorFilter(this);
    m_filter->setFrameModel(m_model);

    auto *body = new QWidget(this);
    buildControls(body);
    buildView(body);
    layOut(body);
    setWidget(body);

    // Items (texts in retranslate()) before the signals: an empty combo picks its first item.
    for (int flags : {int(FrameMonitorFilter::AllDirections), int(FrameMonitorFilter::Tx | FrameMonitorFilter::Rx),
                      int(FrameMonitorFilter::Tx), int(FrameMonitorFilter::Rx), int(FrameMonitorFilter::Discarded)})
        m_direction->addItem(QString(), flags);
    m_link->addItem(QString());
    connectControls();

    retranslate();
}

void FrameMonitorDock::buildControls(QWidget *body)
{
    m_pause = toolButton(body, QStringLiteral("framePause"), style()->standardIcon(QStyle::SP_MediaPause));
    m_pause->setCheckable(true);
    m_clear = toolButton(body, QStringLiteral("frameClear"), style()->standardIcon(QStyle::SP_DialogResetButton));
    m_save = toolButton(body, QStringLiteral("frameSave"), style()->standardIcon(QStyle::SP_DialogSaveButton));
    m_text = new QLineEdit(body);
    m_text->setObjectName(QStringLiteral("frameFilterText"));
    m_text->setClearButtonEnabled(true);
    m_direction = new QComboBox(body);
    m_direction->setObjectName(QStringLiteral("frameFilterDirection"));
    m_link = new QComboBox(body);
    m_link->setObjectName(QStringLiteral("frameFilterLink"));
    m_link->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_follow = new QCheckBox(body);
    m_follow->setObjectName(QStringLiteral("frameFollow"));
    m_follow->setChecked(true);
    m_counts = new QLabel(body);
    m_counts->setObjectName(QStringLiteral("frameCounts"));
}

void FrameMonitorDock::buildView(QWidget *body)
{
    m_view = new QTreeView(body);
    m_view->setObjectName(QStringLiteral("frameView"));
    m_view->setModel(m_filter);
    m_view->setRootIsDecorated(false);
    m_view->setUniformRowHeights(true); // 50k rows stay cheap to lay out
    m_view->setAlternatingRowColors(true);
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->header()->setStretchLastSection(true);
    m_view->header()->resizeSection(FrameMonitorModel::TimeColumn, 100);
    m_view->header()->resizeSection(FrameMonitorModel::LinkColumn, 140);
    m_view->header()->resizeSection(FrameMonitorModel::DirectionColumn, 50);
    m_view->header()->resizeSection(FrameMonitorModel::DataColumn, 260);
}

void FrameMonitorDock::layOut(QWidget *body)
{
    auto *bar = new QHBoxLayout;
    bar->addWidget(m_pause);
    bar->addWidget(m_clear);
    bar->addWidget(m_save);
    bar->addSpacing(8);
    bar->addWidget(m_text, 2);
    bar->addWidget(m_direction);
    bar->addWidget(m_link, 1);
    bar->addWidget(m_follow);
    auto *layout = new QVBoxLayout(body);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(bar);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_counts);
}

void FrameMonitorDock::connectControls()
{
    connect(m_pause, &QToolButton::toggled, this, &FrameMonitorDock::setPaused);
    connect(m_clear, &QToolButton::clicked, m_model, &FrameMonitorModel::clear);
    connect(m_save, &QToolButton::clicked, this, &FrameMonitorDock::save);
    connect(m_text, &QLineEdit::textChanged, m_filter, &FrameMonitorFilter::setText);
    connect(m_direction, &QComboBox::currentIndexChanged, this, &FrameMonitorDock::updateDirections);
    connect(m_link, &QComboBox::currentIndexChanged, this,
            [this](int i) { m_filter->setLink(i > 0 ? m_link->itemData(i).toString() : QString()); });
    connect(m_model, &FrameMonitorModel::linksChanged, this, &FrameMonitorDock::updateLinks);
    connect(m_model, &FrameMonitorModel::countsChanged, this, &FrameMonitorDock::updateCounts);
    connect(m_filter, &QAbstractItemModel::rowsInserted, this, [this] {
        if (m_follow->isChecked())
            m_view->scrollToBottom();
        updateCounts();
    });
    connect(m_filter, &QAbstractItemModel::rowsRemoved, this, &FrameMonitorDock::updateCounts);
    connect(m_filter, &QAbstractItemModel::modelReset, this, &FrameMonitorDock::updateCounts);
}

void FrameMonitorDock::setPaused(bool paused)
{
    m_model->setPaused(paused);
    if (m_pause->isChecked() != paused)
        m_pause->setChecked(paused);
    updateCounts();
}

bool FrameMonitorDock::isPaused() const
{
    return m_model->isPaused();
}

Error FrameMonitorDock::saveTo(const QString &path) const
{
    QList<TrafficLog::Entry> entries;
    const int rows = m_filter->rowCount();
    entries.reserve(rows);
    for (int i = 0; i < rows; ++i)
        entries.append(m_model->entry(m_filter->mapToSource(m_filter->index(i, 0)).row()));
    return TrafficLog::save(path, entries);
}

void FrameMonitorDock::save()
{
    const QString name = QStringLiteral("frames-%1.csv")
                             .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")));
    const QString path = QFileDialog::getSaveFileName(this, tr("Save frames"), QDir::home().filePath(name),
                                                      tr("CSV files (*.csv);;Text files (*.txt *.log)"));
    if (path.isEmpty())
        return;
    if (const Error e = saveTo(path))
        emit errorOccurred(e);
}

void FrameMonitorDock::updateDirections()
{
    m_filter->setDirections(FrameMonitorFilter::Directions(m_direction->currentData().toInt()));
}

void FrameMonitorDock::updateLinks()
{
    const QStringList links = m_model->links();
    // Links are only ever added: the combo has "All links" and the ones seen so far.
    for (int i = m_link->count() - 1; i < links.size(); ++i)
        m_link->addItem(links.at(i), links.at(i));
}

void FrameMonitorDock::updateCounts()
{
    const QLocale locale;
    QString text = tr("%1 frames, %2 shown")
                       .arg(locale.toString(m_model->rowCount()), locale.toString(m_filter->rowCount()));
    if (m_model->isPaused())
        text += QStringLiteral(" — ") + tr("paused: %1 new frames wait").arg(locale.toString(m_model->heldCount()));
    if (m_model->droppedCount())
        text += QStringLiteral(" — ")
            + tr("%1 oldest frames dropped (the monitor keeps the last %2)")
                  .arg(locale.toString(qulonglong(m_model->droppedCount())), locale.toString(m_model->capacity()));
    m_counts->setText(text);
}

void FrameMonitorDock::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDockWidget::changeEvent(event);
}

void FrameMonitorDock::retranslate()
{
    setWindowTitle(tr("Frame monitor"));
    m_pause->setText(tr("&Pause"));
    m_pause->setToolTip(tr("Hold the view still. Frames are still recorded and appear when you resume."));
    m_clear->setText(tr("C&lear"));
    m_clear->setToolTip(tr("Forget every recorded frame"));
    m_save->setText(tr("&Save…"));
    m_save->setToolTip(tr("Save the frames shown (with the filter applied) as CSV or text"));
    m_text->setPlaceholderText(tr("Filter: hex bytes, meaning, link…"));
    m_direction->setItemText(0, tr("All directions"));
    m_direction->setItemText(1, tr("TX and RX"));
    m_direction->setItemText(2, tr("TX only"));
    m_direction->setItemText(3, tr("RX only"));
    m_direction->setItemText(4, tr("Discarded only"));
    m_direction->setToolTip(tr("TX: sent by DriveDesk; RX: received; discarded: bytes that were not a valid reply"));
    m_link->setItemText(0, tr("All links"));
    m_follow->setText(tr("&Follow"));
    m_follow->setToolTip(tr("Keep the newest frame in view"));
    m_model->retranslate();
    updateCounts();
}

} // namespace dd
