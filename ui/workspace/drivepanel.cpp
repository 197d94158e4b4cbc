#include "ui/workspace/drivepanel.h"

#include "core/drive/driveresult.h"
#include "core/protocol/familytraits.h"
#include "ui/common/livetext.h"
#include "ui/workspace/alarmlog.h"
#include "ui/workspace/driveparameters.h"

#include <QEvent>
#include <QLabel>
#include <QLocale>
#include <QPointer>
#include <QProgressBar>
#include <QTime>

namespace dd {

namespace {
const char *const ProblemAtProperty = "ddProblemAt";
const char *const ProblemTextProperty = "ddProblemText";
} // namespace

DrivePanel::DrivePanel(const DriveContext &context, QWidget *parent)
    : QWidget(parent)
    , m_context(context)
{
    m_info.connectionId = context.connectionId;
    m_info.address = context.address;
    m_info.identity.family = context.family;
    m_info.identity.address = context.address;
    m_info.capabilities = context.capabilities;
    if (!m_context.parameters)
        m_context.parameters = new DriveParameters(familyTraits(context.family).eeOperations, this);
    if (!m_context.alarms)
        m_context.alarms = new AlarmLog(this);
}

void DrivePanel::setActive(bool active)
{
    if (m_active == active)
        return;
    m_active = active;
    activeChanged(active);
}

void DrivePanel::setDriveInfo(const DriveInfo &info)
{
    m_info = info;
    m_context.capabilities = info.capabilities;
    driveInfoChanged(info);
}

void DrivePanel::setStatus(const DriveStatus &status)
{
    m_info.status = status;
    statusChanged(status);
}

void DrivePanel::setAlarm(int code)
{
    m_info.status.alarmCode = code;
    alarmChanged(code);
}

void DrivePanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        emit titleChanged();
    }
    QWidget::changeEvent(event);
}

bool DrivePanel::reportResult(const DriveResult &result)
{
    if (!result.ok())
        reportError(result.error);
    else
        ageProblems();
    return result.ok();
}

void DrivePanel::ageProblems()
{
    for (QLabel *label : findChildren<QLabel *>()) {
        const QVariant at = label->property(ProblemAtProperty);
        if (!at.isValid())
            continue;
        std::function<QString()> make = LiveText::maker(label);
        const QString shown = label->property(ProblemTextProperty).toString();
        if (!make)
            make = [shown] { return shown; };
        if (label->text() != make()) // replaced by other means since
            continue;
        const QTime time = at.toTime();
        showMessage(
            label,
            [make, time] {
                return tr("Earlier, at %1: %2").arg(QLocale().toString(time, QStringLiteral("HH:mm:ss")), make());
            },
            MessageKind::EarlierProblem);
    }
}

void DrivePanel::reportError(const Error &error)
{
    if (error.isError())
        emit errorOccurred(error);
}

QLabel *DrivePanel::createMessageLabel(QWidget *parent, const QString &objectName)
{
    auto *label = new QLabel(parent);
    label->setObjectName(objectName);
    label->setWordWrap(true);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

void DrivePanel::showMessage(QLabel *label, std::function<QString()> text, MessageKind kind)
{
    showMessage(label, QString(), kind);
    LiveText::set(label, std::move(text));
}

void DrivePanel::showMessage(QLabel *label, const QString &text, MessageKind kind)
{
    LiveText::clear(label);
    label->setText(text);
    // A problem line remembers when it came (ageProblems()).
    label->setProperty(ProblemAtProperty, kind == MessageKind::Problem ? QVariant(QTime::currentTime()) : QVariant());
    label->setProperty(ProblemTextProperty, kind == MessageKind::Problem ? QVariant(text) : QVariant());
    switch (kind) {
    case MessageKind::Info: label->setStyleSheet(QString()); break;
    case MessageKind::Success: label->setStyleSheet(QStringLiteral("color: #2e7d32;")); break;
    case MessageKind::Problem: label->setStyleSheet(QStringLiteral("color: #c62828;")); break;
    case MessageKind::EarlierProblem:
    case MessageKind::Outdated: label->setStyleSheet(QStringLiteral("color: #757575;")); break;
    case MessageKind::Warning: label->setStyleSheet(QStringLiteral("color: #e65100;")); break;
    }
}

QProgressBar *DrivePanel::createProgressBar(QWidget *parent)
{
    auto *bar = new QProgressBar(parent);
    bar->setMaximumWidth(220);
    bar->hide();
    return bar;
}

std::function<void(int, int)> DrivePanel::progressOn(QProgressBar *bar)
{
    return [bar = QPointer<QProgressBar>(bar)](int done, int total) {
        if (bar && total > 0) {
            bar->setRange(0, total);
            bar->setValue(done);
        }
    };
}

QLabel *DrivePanel::createReasonLabel(QWidget *parent)
{
    auto *label = new QLabel(parent);
    label->setWordWrap(true);
    label->setForegroundRole(QPalette::PlaceholderText);
    label->hide();
    return label;
}

} // namespace dd
