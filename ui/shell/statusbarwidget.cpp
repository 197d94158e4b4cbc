#include "ui/shell/statusbarwidget.h"

#include "core/drive/drivehub.h"
#include "ui/bus/drivedirectory.h"

#include <QContextMenuEvent>
#include <QEvent>
#include <QLabel>
#include <QMenu>

namespace dd {

namespace {
constexpr int MessageTimeoutMs = 8000;
}

StatusBarWidget::StatusBarWidget(DriveHub *hub, DriveDirectory *directory, QWidget *parent)
    : QStatusBar(parent)
    , m_hub(hub)
    , m_directory(directory)
{
    m_link = new QLabel(this);
    m_fpsLabel = new QLabel(this);
    m_errorsLabel = new QLabel(this);
    m_retriesLabel = new QLabel(this);
    m_link->setObjectName(QStringLiteral("linkState"));
    m_fpsLabel->setObjectName(QStringLiteral("framesPerSecond"));
    m_errorsLabel->setObjectName(QStringLiteral("errorCount"));
    m_retriesLabel->setObjectName(QStringLiteral("retryCount"));
    for (QLabel *l : {m_link, m_fpsLabel, m_errorsLabel, m_retriesLabel})
        l->setContentsMargins(8, 0, 8, 0);
    addPermanentWidget(m_link);
    addPermanentWidget(m_fpsLabel);
    addPermanentWidget(m_errorsLabel);
    addPermanentWidget(m_retriesLabel);

    connect(hub, &DriveHub::trafficRecorded, this, &StatusBarWidget::onTraffic);
    connect(directory, &DriveDirectory::connectionAdded, this, &StatusBarWidget::updateLinkState);
    connect(directory, &DriveDirectory::connectionRemoved, this, &StatusBarWidget::updateLinkState);
    connect(directory, &DriveDirectory::linkStateChanged, this, &StatusBarWidget::updateLinkState);
    connect(directory, &DriveDirectory::errorOccurred, this, &StatusBarWidget::countError);

    m_liveTimeout.setSingleShot(true);
    connect(&m_liveTimeout, &QTimer::timeout, this, [this] {
        m_liveText = nullptr;
        clearMessage();
    });
    connect(this, &QStatusBar::messageChanged, this, &StatusBarWidget::onMessageChanged);
    m_tick.setInterval(1000);
    connect(&m_tick, &QTimer::timeout, this, &StatusBarWidget::onTick);
    m_tick.start();
    m_window.start();
    retranslate();
}

void StatusBarWidget::countError(const Error &error)
{
    if (!error.isError() || error.code == ErrorCode::Cancelled)
        return;
    ++m_errors;
    updateCounters();
    if (!error.message.isEmpty())
        showMessage(error.message, MessageTimeoutMs);
}

void StatusBarWidget::showLiveMessage(std::function<QString()> text, int timeoutMs)
{
    m_liveText = std::move(text);
    m_liveShown = m_liveText();
    showMessage(m_liveShown);
    if (timeoutMs > 0)
        m_liveTimeout.start(timeoutMs);
    else
        m_liveTimeout.stop();
}

void StatusBarWidget::onMessageChanged(const QString &text)
{
    // Another message replaced the live one (or it was cleared): forget its maker.
    if (m_liveText && text != m_liveShown) {
        m_liveText = nullptr;
        m_liveTimeout.stop();
    }
}

void StatusBarWidget::resetCounters()
{
    m_errors = 0;
    m_retries = 0;
    updateCounters();
}

void StatusBarWidget::onTraffic(int, const TrafficRecord &record)
{
    ++m_framesInWindow;
    if (record.direction == TrafficRecord::Direction::Discarded) {
        ++m_errors;
        updateCounters();
    } else if (record.direction == TrafficRecord::Direction::Tx && record.note.contains(QLatin1String("(retry "))) {
        ++m_retries;
        updateCounters();
    }
}

void StatusBarWidget::onTick()
{
    const qint64 ms = m_window.restart();
    m_fps = ms > 0 ? double(m_framesInWindow) * 1000.0 / double(ms) : 0.0;
    m_framesInWindow = 0;
    updateCounters();
}

void StatusBarWidget::updateLinkState()
{
    const QList<int> ids = m_directory->connections();
    int lost = 0;
    QString lostName;
    for (int id : ids)
        if (m_directory->linkState(id) == DriveDirectory::LinkState::Lost) {
            ++lost;
            lostName = m_directory->connectionSettings(id).linkName();
        }
    QString text;
    QString style;
    if (ids.isEmpty()) {
        text = tr("Not connected");
    } else if (lost) {
        text = tr("Link lost: %1").arg(lostName);
        style = QStringLiteral("color: #c62828; font-weight: bold;");
    } else if (ids.size() == 1) {
        text = tr("Connected: %1").arg(m_directory->connectionSettings(ids.first()).linkName());
    } else {
        text = tr("%n link(s) open", nullptr, int(ids.size()));
    }
    m_link->setText(text);
    m_link->setStyleSheet(style);
    QStringList tip;
    for (int id : ids)
        tip << QStringLiteral("%1 (%2)").arg(m_directory->connectionSettings(id).linkName(),
                                             familyId(m_directory->connectionSettings(id).family));
    m_link->setToolTip(tip.join(QLatin1Char('\n')));
}

void StatusBarWidget::updateCounters()
{
    m_fpsLabel->setText(tr("%1 frames/s").arg(m_fps, 0, 'f', m_fps < 10 ? 1 : 0));
    m_errorsLabel->setText(tr("Errors: %1").arg(m_errors));
    m_retriesLabel->setText(tr("Retries: %1").arg(m_retries));
    m_errorsLabel->setStyleSheet(m_errors ? QStringLiteral("color: #c62828;") : QString());
}

void StatusBarWidget::contextMenuEvent(QContextMenuEvent *event)
{
    QMenu menu(this);
    menu.addAction(tr("Reset error and retry counts"), this, &StatusBarWidget::resetCounters);
    menu.exec(event->globalPos());
}

void StatusBarWidget::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QStatusBar::changeEvent(event);
}

void StatusBarWidget::retranslate()
{
    m_fpsLabel->setToolTip(tr("Frames sent and received per second, all links"));
    m_errorsLabel->setToolTip(tr("Discarded frames (bad checksum, garbage, late replies), lost "
                                 "links and failed operations. Right-click to reset."));
    m_retriesLabel->setToolTip(tr("Requests sent again after a timeout or a corrupt reply"));
    if (m_liveText) {
        m_liveShown = m_liveText();
        showMessage(m_liveShown);
    }
    updateLinkState();
    updateCounters();
}

} // namespace dd
