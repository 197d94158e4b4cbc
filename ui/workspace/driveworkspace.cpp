#include "ui/workspace/driveworkspace.h"

#include "core/protocol/familytraits.h"
#include "ui/bus/drivedirectory.h"
#include "ui/workspace/alarmlog.h"
#include "ui/workspace/drivepanel.h"
#include "ui/workspace/drivepanels.h"
#include "ui/workspace/driveparameters.h"

#include <QEvent>
#include <QLabel>
#include <QTabWidget>

namespace dd {

namespace {
QStringList channelNames(const DriveInfo &info)
{
    QStringList out;
    for (const ChannelInfo &c : info.channels)
        out << c.name;
    return out;
}
} // namespace

DriveWorkspace::DriveWorkspace(DriveDirectory *directory, QWidget *parent)
    : QStackedWidget(parent)
    , m_directory(directory)
{
    m_hint = new QLabel(this);
    m_hint->setAlignment(Qt::AlignCenter);
    m_hint->setWordWrap(true);
    m_hint->setMargin(24);
    addWidget(m_hint);
    retranslate();

    connect(directory, &DriveDirectory::connectionRemoved, this, &DriveWorkspace::removeConnection);
    connect(directory, &DriveDirectory::driveChanged, this, &DriveWorkspace::onDriveChanged);
    // Alarm history from discovery on, whether or not the drive's tabs were ever opened.
    connect(directory, &DriveDirectory::driveAdded, this, [this](int id, int address) {
        const DriveStatus s = m_directory->info(id, address).status;
        AlarmLog *log = alarmLog(id, address);
        if (s.updatedMs || s.alarmCode)
            log->record(s.alarmCode);
    });
    connect(directory, &DriveDirectory::statusChanged, this, [this](int id, int address, const DriveStatus &s) {
        for (DrivePanel *p : panelsFor(id, address))
            p->setStatus(s);
    });
    connect(directory, &DriveDirectory::alarmChanged, this, [this](int id, int address, int code) {
        alarmLog(id, address)->record(code);
        for (DrivePanel *p : panelsFor(id, address))
            p->setAlarm(code);
    });
}

void DriveWorkspace::showDrive(int id, int address)
{
    const Key key(id, address);
    if (key == m_current)
        return;
    QTabWidget *tabs = nullptr;
    if (id > 0 && m_directory->hasDrive(id, address)) {
        tabs = m_tabs.value(key);
        if (!tabs)
            tabs = createTabs(id, address);
    }
    m_current = tabs ? key : Key(0, 0);
    if (tabs) {
        // Keep the tab the user was looking at, if this drive has it too.
        for (int i = 0; i < tabs->count(); ++i)
            if (auto *p = qobject_cast<DrivePanel *>(tabs->widget(i)); p && p->panelId() == m_currentPanelId)
                tabs->setCurrentIndex(i);
        setCurrentWidget(tabs);
    } else {
        setCurrentWidget(m_hint);
    }
    updateActive();
    emit currentDriveChanged(m_current.first, m_current.second);
}

DriveContext DriveWorkspace::currentDrive() const
{
    const QList<DrivePanel *> panels = panelsFor(m_current.first, m_current.second);
    return panels.isEmpty() ? DriveContext() : panels.first()->context();
}

QTabWidget *DriveWorkspace::tabsFor(int id, int address) const
{
    return m_tabs.value(Key(id, address));
}

QList<DrivePanel *> DriveWorkspace::panelsFor(int id, int address) const
{
    QList<DrivePanel *> out;
    if (QTabWidget *tabs = tabsFor(id, address))
        for (int i = 0; i < tabs->count(); ++i)
            if (auto *p = qobject_cast<DrivePanel *>(tabs->widget(i)))
                out.append(p);
    return out;
}

DriveParameters *DriveWorkspace::parametersFor(int id, int address) const
{
    QTabWidget *tabs = tabsFor(id, address);
    return tabs ? tabs->findChild<DriveParameters *>(QStringLiteral("driveParameters"), Qt::FindDirectChildrenOnly)
                : nullptr;
}

void DriveWorkspace::setPreferredPanel(const QString &panelId)
{
    m_currentPanelId = panelId;
    if (QTabWidget *tabs = tabsFor(m_current.first, m_current.second))
        for (int i = 0; i < tabs->count(); ++i)
            if (auto *p = qobject_cast<DrivePanel *>(tabs->widget(i)); p && p->panelId() == panelId)
                tabs->setCurrentIndex(i);
}

bool DriveWorkspace::openFile(const QString &path)
{
    QTabWidget *tabs = tabsFor(m_current.first, m_current.second);
    if (!tabs)
        return false;
    for (int i = 0; i < tabs->count(); ++i) {
        auto *p = qobject_cast<DrivePanel *>(tabs->widget(i));
        if (p && p->openFile(path)) {
            tabs->setCurrentIndex(i);
            return true;
        }
    }
    return false;
}

QTabWidget *DriveWorkspace::createTabs(int id, int address)
{
    const DriveInfo info = m_directory->info(id, address);
    DriveContext ctx;
    ctx.hub = m_directory->hub();
    ctx.connectionId = id;
    ctx.address = address;
    ctx.family = info.identity.family;
    ctx.capabilities = info.capabilities;
    // One set of parameter values per drive, shared by every panel; the tab set owns it (a
    // child made after the panels, so it goes after them).
    auto *parameters = new DriveParameters(familyTraits(ctx.family).eeOperations);
    parameters->setObjectName(QStringLiteral("driveParameters"));
    ctx.parameters = parameters;
    ctx.alarms = alarmLog(id, address);

    auto *tabs = new QTabWidget(this);
    tabs->setDocumentMode(true);
    for (DrivePanel *p : createDrivePanels(ctx, tabs)) {
        tabs->addTab(p, p->title());
        if (info.valid)
            p->setDriveInfo(info);
        connect(p, &DrivePanel::errorOccurred, this, &DriveWorkspace::errorOccurred);
        connect(p, &DrivePanel::fileUsed, this, &DriveWorkspace::fileUsed);
        connect(p, &DrivePanel::titleChanged, tabs, [tabs, p] {
            const int i = tabs->indexOf(p);
            if (i >= 0)
                tabs->setTabText(i, p->title());
        });
    }
    parameters->setParent(tabs);
    connect(tabs, &QTabWidget::currentChanged, this, [this, tabs] {
        if (auto *p = qobject_cast<DrivePanel *>(tabs->currentWidget()); p && currentWidget() == tabs)
            m_currentPanelId = p->panelId();
        updateActive();
    });
    if (auto *p = qobject_cast<DrivePanel *>(tabs->currentWidget()); p && m_currentPanelId.isEmpty())
        m_currentPanelId = p->panelId();
    addWidget(tabs);
    m_tabs.insert(Key(id, address), tabs);
    return tabs;
}

AlarmLog *DriveWorkspace::alarmLog(int id, int address)
{
    AlarmLog *&log = m_alarmLogs[Key(id, address)];
    if (!log)
        log = new AlarmLog(this);
    return log;
}

void DriveWorkspace::removeConnection(int id)
{
    if (m_current.first == id)
        showDrive(0, 0);
    for (auto it = m_tabs.begin(); it != m_tabs.end();) {
        if (it.key().first == id) {
            removeWidget(it.value());
            delete it.value();
            it = m_tabs.erase(it);
        } else {
            ++it;
        }
    }
    // After the panels that used them.
    for (auto it = m_alarmLogs.begin(); it != m_alarmLogs.end();) {
        if (it.key().first == id) {
            delete it.value();
            it = m_alarmLogs.erase(it);
        } else {
            ++it;
        }
    }
}

void DriveWorkspace::onDriveChanged(int id, int address)
{
    if (!m_tabs.contains(Key(id, address)))
        return;
    const DriveInfo info = m_directory->info(id, address);
    if (!info.valid)
        return;
    for (DrivePanel *p : panelsFor(id, address))
        if (p->driveInfo().capabilities != info.capabilities
            || p->driveInfo().unsupportedReasons != info.unsupportedReasons
            || channelNames(p->driveInfo()) != channelNames(info)
            || p->driveInfo().identity.firmware != info.identity.firmware
            || p->driveInfo().identity.model != info.identity.model || !p->driveInfo().valid)
            p->setDriveInfo(info);
}

void DriveWorkspace::updateActive()
{
    for (auto it = m_tabs.cbegin(); it != m_tabs.cend(); ++it) {
        const bool shown = it.key() == m_current;
        for (int i = 0; i < it.value()->count(); ++i)
            if (auto *p = qobject_cast<DrivePanel *>(it.value()->widget(i)))
                p->setActive(shown && it.value()->currentIndex() == i);
    }
}

void DriveWorkspace::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QStackedWidget::changeEvent(event);
}

void DriveWorkspace::retranslate()
{
    m_hint->setText(tr("Select a drive in the bus tree.\n\nNo drive yet? Use File → Connect… to open "
                       "a serial port or a CAN interface and scan it, or File → Demo bench to "
                       "try DriveDesk with simulated drives."));
}

} // namespace dd
