#include "ui/panels/overview/overviewpanel.h"

#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "core/drive/drivereply.h"
#include "ui/common/displaytext.h"

#include <QDateTime>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPointer>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace dd {

namespace {
QLabel *valueLabel(QWidget *parent)
{
    auto *l = new QLabel(parent);
    l->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return l;
}
} // namespace

OverviewPanel::OverviewPanel(const DriveContext &context, QWidget *parent)
    : DrivePanel(context, parent)
{
    m_identityBox = new QGroupBox(this);
    m_identityForm = new QFormLayout(m_identityBox);
    for (QLabel **l : {&m_family, &m_address, &m_model, &m_firmware, &m_link}) {
        *l = valueLabel(m_identityBox);
        m_identityLabels.append(new QLabel(m_identityBox));
        m_identityForm->addRow(m_identityLabels.last(), *l);
    }

    m_statusBox = new QGroupBox(this);
    m_statusForm = new QFormLayout(m_statusBox);
    for (QLabel **l : {&m_online, &m_motion, &m_enabled, &m_position, &m_alarm, &m_updated}) {
        *l = valueLabel(m_statusBox);
        m_statusLabels.append(new QLabel(m_statusBox));
        m_statusForm->addRow(m_statusLabels.last(), *l);
    }

    m_capsBox = new QGroupBox(this);
    auto *capsLayout = new QVBoxLayout(m_capsBox);
    m_caps = new QTableWidget(m_capsBox);
    m_caps->setObjectName(QStringLiteral("capabilities"));
    m_caps->setColumnCount(2);
    m_caps->setSelectionMode(QAbstractItemView::NoSelection);
    m_caps->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_caps->setShowGrid(false);
    m_caps->verticalHeader()->hide();
    m_caps->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_caps->horizontalHeader()->setStretchLastSection(true);
    m_caps->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    capsLayout->addWidget(m_caps, 1);
    m_reasons = new QLabel(m_capsBox);
    m_reasons->setObjectName(QStringLiteral("capabilityReasons"));
    m_reasons->setWordWrap(true);
    m_reasons->setTextFormat(Qt::RichText);
    m_reasons->hide();
    capsLayout->addWidget(m_reasons);

    m_refresh = new QPushButton(this);
    connect(m_refresh, &QPushButton::clicked, this, &OverviewPanel::refresh);

    auto *left = new QVBoxLayout;
    left->addWidget(m_identityBox);
    left->addWidget(m_statusBox);
    left->addStretch(1);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_refresh);
    buttons->addStretch(1);
    left->addLayout(buttons);

    auto *layout = new QHBoxLayout(this);
    layout->addLayout(left, 2);
    layout->addWidget(m_capsBox, 3);

    retranslate();
}

QString OverviewPanel::title() const
{
    return tr("Overview");
}

void OverviewPanel::refresh()
{
    if (!context().isValid())
        return;
    m_refresh->setEnabled(false);
    QPointer<OverviewPanel> self(this);
    fetchDriveInfo(context().hub, context().connectionId, context().address,
                   [self](const DriveInfo &info, const Error &error) {
                       if (!self)
                           return;
                       self->m_refresh->setEnabled(true);
                       if (info.valid)
                           self->setDriveInfo(info);
                       self->reportError(error);
                   });
    context().hub->run(
        context().connectionId, context().address, [](Drive &d) { return d.readStatus(); },
        [self](const DriveResult &r) {
            if (self)
                self->reportResult(r);
        });
}

void OverviewPanel::driveInfoChanged(const DriveInfo &)
{
    showIdentity();
    showCapabilities();
    showStatus();
}

void OverviewPanel::statusChanged(const DriveStatus &)
{
    showStatus();
}

void OverviewPanel::alarmChanged(int)
{
    showStatus();
}

void OverviewPanel::retranslate()
{
    m_identityBox->setTitle(tr("Identity"));
    m_statusBox->setTitle(tr("Status"));
    m_capsBox->setTitle(tr("Capabilities"));
    const QStringList identityRows{tr("Family:"), tr("Address:"), tr("Model:"), tr("Firmware:"), tr("Link:")};
    for (int i = 0; i < identityRows.size(); ++i)
        m_identityLabels.at(i)->setText(identityRows.at(i));
    const QStringList statusRows{tr("Communication:"), tr("Motion:"), tr("Power stage:"),
                                 tr("Position:"),      tr("Alarm:"),  tr("Last update:")};
    for (int i = 0; i < statusRows.size(); ++i)
        m_statusLabels.at(i)->setText(statusRows.at(i));
    m_caps->setHorizontalHeaderLabels({tr("Function"), tr("Available")});
    m_refresh->setText(tr("Refresh"));
    m_refresh->setToolTip(tr("Read the identity and the status of the drive again"));
    showIdentity();
    showCapabilities();
    showStatus();
}

void OverviewPanel::showIdentity()
{
    const DriveIdentity &id = driveInfo().identity;
    const QString unknown = tr("unknown");
    m_family->setText(
        QStringLiteral("%1 (%2)").arg(DisplayText::familyName(context().family), familyId(context().family)));
    m_address->setText(QString::number(context().address));
    m_model->setText(id.model.isEmpty() ? unknown : id.model);
    m_firmware->setText(id.firmware.isEmpty() ? unknown : id.firmware);
    m_link->setText(id.link.isEmpty() ? unknown : id.link);
}

void OverviewPanel::showCapabilities()
{
    // A family usually gives one reason for several missing functions: each distinct reason
    // is written once under the table and referred to by number.
    const DriveInfo &info = driveInfo();
    const QList<Capability> all = DriveInfo::allCapabilities();
    QStringList reasons;
    m_caps->setRowCount(int(all.size()));
    for (int row = 0; row < all.size(); ++row) {
        const Capability c = all.at(row);
        auto *name = new QTableWidgetItem(DriveInfo::capabilityName(c));
        auto *value = new QTableWidgetItem;
        if (info.capabilities.testFlag(c)) {
            value->setText(tr("Yes"));
        } else {
            const QString reason = info.reason(c);
            if (!reason.isEmpty() && !reasons.contains(reason))
                reasons.append(reason);
            value->setText(reason.isEmpty() ? tr("No") : tr("No (%1)").arg(reasons.indexOf(reason) + 1));
            value->setToolTip(reason);
            name->setForeground(palette().brush(QPalette::Disabled, QPalette::Text));
            value->setForeground(palette().brush(QPalette::Disabled, QPalette::Text));
        }
        m_caps->setItem(row, 0, name);
        m_caps->setItem(row, 1, value);
    }
    QStringList notes;
    for (int i = 0; i < reasons.size(); ++i)
        notes << QStringLiteral("(%1) %2").arg(i + 1).arg(reasons.at(i).toHtmlEscaped());
    m_reasons->setText(notes.join(QStringLiteral("<br>")));
    m_reasons->setVisible(!notes.isEmpty());
}

void OverviewPanel::showStatus()
{
    const DriveStatus &s = driveInfo().status;
    m_online->setText(s.online ? tr("Online") : (s.updatedMs ? tr("No answer") : tr("Not polled yet")));
    m_motion->setText(DisplayText::motionState(s));
    m_enabled->setText(DisplayText::enabledState(s));
    m_position->setText(DisplayText::position(s));
    m_alarm->setText(DisplayText::alarm(s.alarmCode));
    m_alarm->setStyleSheet(s.alarmCode ? QStringLiteral("color: #c62828; font-weight: bold;") : QString());
    m_updated->setText(s.updatedMs ? QLocale().toString(QDateTime::fromMSecsSinceEpoch(s.updatedMs).time(),
                                                        QStringLiteral("HH:mm:ss.zzz"))
                                   : QStringLiteral("—"));
}

} // namespace dd
